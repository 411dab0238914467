#include "dds/input_publisher.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "core/error.hpp"
#include "dds/ros_messages.hpp"
#include "geometry_msgs/msg/PoseStamped.h"
#include "onetip_msgs/msg/InputEvent.h"
#include "pipeline/frame_processor.hpp"
#include "sensor_msgs/msg/Joy.h"
#include "sensor_msgs/msg/PointCloud2.h"
#include "std_msgs/msg/Float64MultiArray.h"

namespace onetip::dds {
namespace {

std_msgs_msg_dds__Header_ header(double t, const std::string& frame_id) {
  const RosTime s = rosTime(t);
  std_msgs_msg_dds__Header_ h{};
  h.stamp.sec = s.sec;
  h.stamp.nanosec = s.nanosec;
  h.frame_id = const_cast<char*>(frame_id.c_str());  // read only: dds_write serialises it
  return h;
}

template <typename Seq, typename T>
Seq sequenceOver(T* data, size_t n) {
  Seq s{};
  s._maximum = s._length = static_cast<uint32_t>(n);
  s._buffer = data;
  s._release = false;
  return s;
}

const InputPublisherOptions& checked(const InputPublisherOptions& o) {
  for (double w : o.working_range)
    if (!(w > 0 && std::isfinite(w))) throw InputError("dds publisher working_range: every entry must be > 0");
  return o;
}

}  // namespace

InputPublisher::InputPublisher(const Participant& p, const InputPublisherOptions& options, const StreamQos& qos)
    : options_(checked(options)),
      frame_id_(sensorFrameId(p.options().ros_namespace)),
      joy_(std::make_unique<Writer>(p, sensor_msgs_msg_dds__Joy__desc, p.topic("joy"), StreamKind::high_rate, qos)),
      input6_(std::make_unique<Writer>(p, std_msgs_msg_dds__Float64MultiArray__desc, p.topic("input6"),
                                       StreamKind::high_rate, qos)),
      pose_(std::make_unique<Writer>(p, geometry_msgs_msg_dds__PoseStamped__desc, p.topic("pose"),
                                     StreamKind::high_rate, qos)),
      markers_(std::make_unique<Writer>(p, sensor_msgs_msg_dds__PointCloud2__desc, p.topic("markers"),
                                        StreamKind::high_rate, qos)),
      events_(std::make_unique<Writer>(p, onetip_msgs_msg_dds__InputEvent__desc, p.topic("events"), StreamKind::events,
                                       qos)),
      transform_(p, options_.parent_frame, frame_id_, qos) {}

InputPublisher::~InputPublisher() = default;

double InputPublisher::stamp(double source_t, std::chrono::steady_clock::time_point arrival) {
  return clock_.stamp(source_t, systemSecondsAt(arrival));
}

void InputPublisher::publishFrame(const pipeline::FrameResult& r, std::chrono::steady_clock::time_point arrival) {
  const input::TrackerResult& p = r.pose;
  const std_msgs_msg_dds__Header_ h = header(stamp(r.t, arrival), frame_id_);

  std::array<float, 6> axes = joyAxes(p.input, options_.working_range);
  std::array<int32_t, 2> buttons{p.pressed ? 1 : 0, p.contact ? 1 : 0};
  sensor_msgs_msg_dds__Joy_ joy{};
  joy.header = h;
  joy.axes = sequenceOver<dds_sequence_float>(axes.data(), axes.size());
  joy.buttons = sequenceOver<dds_sequence_int32>(buttons.data(), buttons.size());
  joy_->write(&joy);

  std::array<double, 6> input = p.input.asArray();
  static const char kAxes[] = "dx,dy,dz,yaw,pitch,roll";
  std_msgs_msg_dds__MultiArrayDimension_ dim{const_cast<char*>(kAxes), 6, 6};  // read only: dds_write serialises it
  std_msgs_msg_dds__Float64MultiArray_ raw{};
  raw.layout.dim = sequenceOver<dds_sequence_std_msgs_msg_dds__MultiArrayDimension_>(&dim, 1);
  raw.layout.data_offset = 0;
  raw.data = sequenceOver<dds_sequence_double>(input.data(), input.size());
  input6_->write(&raw);

  geometry_msgs_msg_dds__PoseStamped_ pose{};
  pose.header = h;
  const auto xyz = positionMetres(p.raw);
  const auto q = quaternionXyzw(p.raw);
  pose.pose.position = {xyz[0], xyz[1], xyz[2]};
  pose.pose.orientation = {q[0], q[1], q[2], q[3]};
  pose_->write(&pose);

  MarkerCloud cloud = markerCloud(r);
  std::vector<sensor_msgs_msg_dds__PointField_> fields;
  for (const CloudField& f : markerCloudFields())
    fields.push_back({const_cast<char*>(f.name), f.offset, f.datatype, 1});
  sensor_msgs_msg_dds__PointCloud2_ pc{};
  pc.header = h;
  pc.height = 1;
  pc.width = cloud.width;
  pc.fields = sequenceOver<dds_sequence_sensor_msgs_msg_dds__PointField_>(fields.data(), fields.size());
  pc.is_bigendian = false;
  pc.point_step = kMarkerPointStep;
  pc.row_step = kMarkerPointStep * cloud.width;
  pc.data = sequenceOver<dds_sequence_uint8>(cloud.data.data(), cloud.data.size());
  pc.is_dense = true;
  markers_->write(&pc);

  ++counts_.frames;
}

void InputPublisher::publishEvent(std::int64_t frame, const input::InputEvent& e,
                                  std::chrono::steady_clock::time_point arrival) {
  if (e.type == EventType::input) return;
  onetip_msgs_msg_dds__InputEvent_ ev{};
  ev.header = header(stamp(e.t, arrival), frame_id_);
  ev.type = static_cast<uint8_t>(e.type);
  ev.state = static_cast<uint8_t>(e.state);
  ev.frame = frame;
  const auto a = e.input.asArray();
  std::copy(a.begin(), a.end(), ev.input);
  ev.message = const_cast<char*>(e.message.c_str());
  events_->write(&ev);
  ++counts_.events;
}

int InputPublisher::matchedReaders() const {
  return std::min({joy_->matchedReaders(), input6_->matchedReaders(), pose_->matchedReaders(),
                   markers_->matchedReaders(), events_->matchedReaders()});
}

bool InputPublisher::waitForReaders(double timeout_s) const {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (matchedReaders() == 0) {
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

}  // namespace onetip::dds
