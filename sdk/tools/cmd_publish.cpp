// `onetip publish`: the sensing pipeline's output on a DDS domain as ROS 2
// topics (dds/input_publisher.hpp: joy, input6, pose, markers, events, and
// the sensor frame's static transform on /tf_static) and, with
// --sensed-stride, the contact field as the haptic channel's sensed vector
// (dds/sensed_vector_link.hpp), until SIGINT/SIGTERM or the source ends.
// docs/dds/README.md has the topics, types, QoS and how ROS 2 reads them.
#include <chrono>
#include <cstdio>
#include <thread>

#include "command.hpp"
#include "core/error.hpp"
#include "dds/input_publisher.hpp"
#include "dds/sensed_vector_link.hpp"
#include "dds_command.hpp"
#include "pipeline_command.hpp"

namespace onetip::tools {
namespace {

// The contact field's displacement u = (dx, dy, dz) (S, mm) of every stride-th
// marker row and column (the last ones included), as OnetipContactSensor
// reads it (haptics/onetip_contact_sensor.hpp): channel 3 k + c.
std::vector<double> sensedField(const pipeline::FrameResult& r, int stride) {
  std::vector<double> out;
  const MarkerField& m = r.markers;
  const auto& u = r.pose.field.displacement;
  auto picks = [stride](int n) {
    std::vector<int> p;
    for (int i = 0; i < n; i += stride) p.push_back(i);
    if (p.empty() || p.back() != n - 1) p.push_back(n - 1);
    return p;
  };
  for (int row : picks(m.rows))
    for (int col : picks(m.cols)) {
      const auto i = static_cast<size_t>(row * m.cols + col);
      const Eigen::Vector3d d = i < u.size() ? u[i] : Eigen::Vector3d::Zero();
      out.insert(out.end(), {d.x(), d.y(), d.z()});
    }
  return out;
}

int runPublish(const Args& args) {
  const dds::DdsOptions dds_options = ddsOptionsFromArgs(args);
  const int stride = args.getInt("sensed-stride", 4);
  if (stride < 0) throw InputError("--sensed-stride " + std::to_string(stride) + ": must be >= 0 (0: off)");
  const std::string sensor_name = args.optional("sensor").value_or("onetip_contact");
  dds::validateSensorName(sensor_name, "--sensor");
  const pipeline::PipelineOptions options = pipelineOptionsFromArgs(args);
  auto pipeline = openPipelineFromArgs(args, options);
  dds::Participant participant(dds_options);
  dds::InputPublisherOptions publishing;
  publishing.working_range = options.processor.pose.working_range;
  publishing.parent_frame = args.optional("tf-parent").value_or(publishing.parent_frame);
  dds::InputPublisher publisher(participant, publishing);
  std::unique_ptr<dds::SensedVectorPublisher> sensed;
  if (stride > 0) sensed = std::make_unique<dds::SensedVectorPublisher>(participant, sensor_name);

  // Both callbacks run on the pipeline's processing thread, a frame's events first.
  pipeline->onEvent([&](const pipeline::PipelineEvent& e) { publisher.publishEvent(e.frame, e.event, e.arrival); });
  pipeline->onFrame([&](const pipeline::PipelineFrame& f) {
    if (f.result.status != pipeline::FrameStatus::ok && f.result.status != pipeline::FrameStatus::reference) return;
    publisher.publishFrame(f.result, f.arrival);
    if (sensed) sensed->publish(f.result.t, sensedField(f.result, stride));
  });
  const double wait_s = args.getDouble("wait-subscribers", 0);
  std::fprintf(stderr, "publishing on domain %d as rt/%s/..., frame %s under %s on rt/tf_static\n",
               dds_options.domain, participant.options().ros_namespace.c_str(), publisher.frameId().c_str(),
               publishing.parent_frame.c_str());
  const int code = runPipelineUntilInterrupted(*pipeline, [&] {
    if (wait_s > 0 && !publisher.waitForReaders(wait_s))
      std::fprintf(stderr, "no subscriber on every topic after %.1f s: publishing anyway\n", wait_s);
    return !interruptRequested();
  });
  // Give reliable events time to be acknowledged before the writers go.
  const double linger_s = args.getDouble("linger", 0.5);
  std::this_thread::sleep_for(std::chrono::duration<double>(std::max(0.0, linger_s)));
  const dds::InputPublisherCounts c = publisher.counts();
  std::fprintf(stderr, "published %llu frames and %llu events\n", static_cast<unsigned long long>(c.frames),
               static_cast<unsigned long long>(c.events));
  return code;
}

std::vector<OptionSpec> publishOptions() {
  std::vector<OptionSpec> o = pipelineInputOptions();
  for (auto& s : ddsOptionSpecs()) o.push_back(s);
  o.push_back({"sensed-stride", "publish the contact field on haptic/sensed, every N-th marker row and column "
                                "(default 4: 75 channels on 17x17; 0: off)", false, false});
  o.push_back({"sensor", "the sensor name announced on haptic/sensed, which `teleop --sensor` follows: 1 .. 64 "
                         "characters of [A-Za-z0-9_.-] (default onetip_contact)", false, false});
  o.push_back({"wait-subscribers", "wait up to this many seconds for a subscriber on every topic (default 0)", false,
               false});
  o.push_back({"tf-parent", "TF parent frame of the sensor frame <namespace>_sensor, published on /tf_static "
                            "(default world)", false, false});
  o.push_back({"linger", "seconds to keep the writers after the source ends (default 0.5)", false, false});
  return o;
}

const CommandRegistrar reg{{"publish",
                            "Publish the 6-D input (sensor_msgs/Joy, std_msgs/Float64MultiArray, "
                            "geometry_msgs/PoseStamped), the markers "
                            "(sensor_msgs/PointCloud2), events and the haptic sensed vector over DDS as ROS 2 "
                            "topics rt/<namespace>/...",
                            publishOptions(), runPublish}};

}  // namespace
}  // namespace onetip::tools
