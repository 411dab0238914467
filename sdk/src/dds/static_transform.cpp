#include "dds/static_transform.hpp"

#include <chrono>

#include "core/error.hpp"
#include "dds/ros_messages.hpp"
#include "tf2_msgs/msg/TFMessage.h"

namespace onetip::dds {

StaticTransformPublisher::StaticTransformPublisher(const Participant& p, std::string parent, std::string child,
                                                   const StreamQos& qos) {
  for (const std::string* frame : {&parent, &child})
    if (!isRosName(*frame))
      throw InputError("tf frame '" + *frame + "': not a ROS name (tokens [A-Za-z_][A-Za-z0-9_]* joined by '/')");
  if (parent == child) throw InputError("tf parent frame '" + parent + "': is the sensor frame itself");
  writer_ = std::make_unique<Writer>(p, tf2_msgs_msg_dds__TFMessage__desc, "rt/tf_static", StreamKind::latched, qos);

  const RosTime now = rosTime(std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count());
  geometry_msgs_msg_dds__TransformStamped_ t{};
  t.header.stamp.sec = now.sec;
  t.header.stamp.nanosec = now.nanosec;
  t.header.frame_id = parent.data();  // read only: dds_write serialises it
  t.child_frame_id = child.data();
  t.transform.translation = {0.0, 0.0, 0.0};
  t.transform.rotation = {0.0, 0.0, 0.0, 1.0};  // x, y, z, w: the identity
  tf2_msgs_msg_dds__TFMessage_ msg{};
  msg.transforms._maximum = msg.transforms._length = 1;
  msg.transforms._buffer = &t;
  msg.transforms._release = false;
  writer_->write(&msg);
}

}  // namespace onetip::dds
