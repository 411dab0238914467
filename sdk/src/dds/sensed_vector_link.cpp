#include "dds/sensed_vector_link.hpp"

#include "dds/ros_messages.hpp"
#include "onetip_msgs/msg/SensedVector.h"

namespace onetip::dds {

SensedVectorPublisher::SensedVectorPublisher(const Participant& p, std::string sensor, const StreamQos& qos)
    : sensor_(std::move(sensor)),
      writer_(p, onetip_msgs_msg_dds__SensedVector__desc, p.topic("haptic/sensed"), StreamKind::high_rate, qos) {}

std::uint64_t SensedVectorPublisher::publish(double stamp_s, const std::vector<double>& values) {
  const RosTime t = rosTime(stamp_s);
  static const char kFrame[] = "";
  onetip_msgs_msg_dds__SensedVector_ s{};
  s.header.stamp.sec = t.sec;
  s.header.stamp.nanosec = t.nanosec;
  s.header.frame_id = const_cast<char*>(kFrame);  // read only: dds_write serialises it
  s.serial = ++sequence_;
  s.sensor = const_cast<char*>(sensor_.c_str());
  s.values._maximum = s.values._length = static_cast<uint32_t>(values.size());
  s.values._buffer = const_cast<double*>(values.data());
  s.values._release = false;
  writer_.write(&s);
  return sequence_;
}

SensedVectorSubscriber::SensedVectorSubscriber(const Participant& p, const std::string& sensor, const StreamQos& qos,
                                               double requested_deadline_s)
    : follower_(sensor),
      reader_(p, onetip_msgs_msg_dds__SensedVector__desc, p.topic("haptic/sensed"), StreamKind::high_rate, qos,
              requested_deadline_s, follower_.topicFilter()) {}

bool SensedVectorSubscriber::takeNewest(SensedSample& out) {
  bool got = false;
  reader_.take([&](const void* sample, const dds_sample_info_t& info) {
    const auto* s = static_cast<const onetip_msgs_msg_dds__SensedVector_*>(sample);
    if (!follower_.taken(info.publication_handle, s ? s->sensor : nullptr,
                         [&] { return reader_.writerGuid(info.publication_handle); }))
      return;
    ++received_;
    if (got && (!out.undecodable.empty() || (s && s->serial <= out.sequence))) return;  // an undecodable one stands
    out.received = std::chrono::steady_clock::now();
    out.latency_ms = static_cast<double>(dds_time() - info.source_timestamp) * 1e-6;
    got = true;
    if (!s) {
      out.undecodable = "a sensed vector not in XCDR1 (its encapsulation), which onetip does not decode";
      out.values.clear();
      return;
    }
    out.undecodable.clear();
    out.sequence = s->serial;
    out.stamp_s = seconds({s->header.stamp.sec, s->header.stamp.nanosec});
    out.sensor = shownSensorName(s->sensor);
    out.values.assign(s->values._buffer, s->values._buffer + s->values._length);
  });
  return got;
}

}  // namespace onetip::dds
