// dds/input_publisher.hpp — publishes each processed frame of the sensing
// pipeline as ROS 2 messages (ros_messages.hpp has the field mapping):
//
//   rt/<ns>/joy      sensor_msgs/Joy           high_rate QoS, every frame: the
//                    6-D input normalised by the working range to [-1, 1]
//   rt/<ns>/input6   std_msgs/Float64MultiArray high_rate QoS, every frame: the
//                    6-D input itself (mm, degrees)
//   rt/<ns>/pose     geometry_msgs/PoseStamped high_rate QoS, every frame
//   rt/<ns>/markers  sensor_msgs/PointCloud2   high_rate QoS, every frame
//   rt/<ns>/events   onetip_msgs/InputEvent    events QoS (reliable), one per
//                    event except `input` (the joy topic carries it), with the
//                    number of the frame it came from
//   rt/tf_static     tf2_msgs/TFMessage        latched QoS, once: the identity
//                    from options.parent_frame to the sensor frame
//
// Each header's stamp is on the system clock (ros_clock.hpp: the source time
// mapped so that the first frame is stamped with its arrival); frame_id is the
// sensor frame S, "<namespace>_sensor" (sensorFrameId). Not thread-safe: one
// publishing thread.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include "dds/endpoint.hpp"
#include "dds/ros_clock.hpp"
#include "dds/static_transform.hpp"
#include "input/input_event.hpp"

namespace onetip::pipeline {
struct FrameResult;
}

namespace onetip::dds {

struct InputPublisherCounts {
  std::uint64_t frames = 0, events = 0;
};

struct InputPublisherOptions {
  // The SensorOptions working range (mm, mm, mm, deg, deg, deg) the Joy axes are normalised by.
  std::array<double, 6> working_range{4, 4, 3, 15, 40, 40};
  std::string parent_frame = "world";  // TF parent of the sensor frame
};

class InputPublisher {
 public:
  // InputError for a working range entry that is not > 0 or a bad parent frame.
  explicit InputPublisher(const Participant& participant, const InputPublisherOptions& options = {},
                          const StreamQos& qos = {});
  ~InputPublisher();

  // joy, input6, pose and markers of one processed frame; arrival: when the
  // frame came from its source (steady clock), which anchors the stamps.
  void publishFrame(const pipeline::FrameResult& r, std::chrono::steady_clock::time_point arrival);
  // One event of the frame `frame` (-1: not tied to a frame) on the events
  // topic; `input` events are skipped (joy carries them).
  void publishEvent(std::int64_t frame, const input::InputEvent& e, std::chrono::steady_clock::time_point arrival);
  const std::string& frameId() const noexcept { return frame_id_; }
  // Smallest number of matched readers over the five per-frame and event topics.
  int matchedReaders() const;
  // Waits until every topic has a matched reader, up to timeout_s; true when they do.
  bool waitForReaders(double timeout_s) const;
  InputPublisherCounts counts() const noexcept { return counts_; }

 private:
  double stamp(double source_t, std::chrono::steady_clock::time_point arrival);

  InputPublisherOptions options_;
  std::string frame_id_;
  std::unique_ptr<Writer> joy_, input6_, pose_, markers_, events_;
  StaticTransformPublisher transform_;
  SourceToSystemClock clock_;
  InputPublisherCounts counts_;
};

}  // namespace onetip::dds
