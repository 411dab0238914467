// dds/input_publisher.hpp — publishes each processed frame of the sensing
// pipeline as ROS 2 messages (ros_messages.hpp has the field mapping):
//
//   rt/<ns>/joy      sensor_msgs/Joy           high_rate QoS, every frame
//   rt/<ns>/pose     geometry_msgs/PoseStamped high_rate QoS, every frame
//   rt/<ns>/markers  sensor_msgs/PointCloud2   high_rate QoS, every frame
//   rt/<ns>/events   onetip_msgs/InputEvent    events QoS (reliable), one per
//                    event except `input` (the joy topic carries it), with the
//                    number of the frame it came from
//
// Each header's stamp is the frame's source timestamp (the scenario time for
// sim: sources, the capture time for cameras); frame_id is `frame_id`
// ("onetip_sensor", the sensor frame S). Not thread-safe: one publishing thread.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "dds/endpoint.hpp"
#include "input/input_event.hpp"

namespace onetip::pipeline {
struct FrameResult;
}

namespace onetip::dds {

struct InputPublisherCounts {
  std::uint64_t frames = 0, events = 0;
};

class InputPublisher {
 public:
  explicit InputPublisher(const Participant& participant, const StreamQos& qos = {},
                          std::string frame_id = "onetip_sensor");
  ~InputPublisher();

  // joy, pose and markers of one processed frame.
  void publishFrame(const pipeline::FrameResult& r);
  // One event of the frame `frame` (-1: not tied to a frame) on the events
  // topic; `input` events are skipped (joy carries them).
  void publishEvent(std::int64_t frame, const input::InputEvent& e);
  // Smallest number of matched readers over the four topics.
  int matchedReaders() const;
  // Waits until every topic has a matched reader, up to timeout_s; true when they do.
  bool waitForReaders(double timeout_s) const;
  InputPublisherCounts counts() const noexcept { return counts_; }

 private:
  std::string frame_id_;
  std::unique_ptr<Writer> joy_, pose_, markers_, events_;
  InputPublisherCounts counts_;
};

}  // namespace onetip::dds
