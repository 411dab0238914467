// dds/static_transform.hpp — the sensor frame's place in ROS 2's TF tree:
// one geometry_msgs/TransformStamped from `parent` to `child` on rt/tf_static
// (tf2_msgs/TFMessage), as ROS 2's static_transform_publisher sends it:
// RELIABLE, TRANSIENT_LOCAL, KEEP_LAST 1 (StreamKind::latched), so a node that
// starts later still receives it, and tf2 can place every message stamped in
// `child` (docs/dds/README.md). The transform is the identity (the sensor frame
// S coincides with `parent`; place the parent where the sensor is mounted),
// stamped with the system time when it is sent. The topic is not under the
// namespace: /tf_static is global in ROS 2, and each sensor's child frame is
// its own (`<namespace>_sensor`, sensorFrameId in participant.hpp).
#pragma once

#include <memory>
#include <string>

#include "dds/endpoint.hpp"

namespace onetip::dds {

class StaticTransformPublisher {
 public:
  // InputError when parent or child is not a ROS name or they are the same frame.
  StaticTransformPublisher(const Participant& participant, std::string parent, std::string child,
                           const StreamQos& qos = {});
  int matchedReaders() const { return writer_->matchedReaders(); }

 private:
  std::unique_ptr<Writer> writer_;
};

}  // namespace onetip::dds
