// dds/ros_messages.hpp — onetip's results as the fields of ROS 2 messages
// (pure conversions, no DDS; docs/dds/README.md has the full mapping).
//
//   stamp: seconds -> builtin_interfaces/Time {sec, nanosec}, nanosec in [0, 1e9).
//   sensor_msgs/Joy: axes = the 6-D input [dx, dy, dz, yaw, pitch, roll]
//       (docs/reference.md order) as a joystick reports it, each axis divided
//       by its working range and clamped: a_i = clamp(v_i / w_i, -1, 1), w_i
//       from SensorOptions::working_range (mm, mm, mm, deg, deg, deg; the
//       half-width of the symmetric range |v_i| <= w_i; dz, a press depth in
//       [0, w], maps onto [0, 1]), as spacenav_node scales a SpaceMouse by its
//       full scale; float32 as Joy defines. buttons = [press button, in contact] (0/1).
//       The unscaled input (mm, degrees) is the input6 topic's Float64MultiArray.
//   geometry_msgs/PoseStamped in frame S ("<namespace>_sensor"), ROS units (m):
//       position = T(c0) - c0 in S = (dx, dy, -dz) * 1e-3 m,
//       orientation = the unit quaternion (x, y, z, w) of
//       R = Rz(yaw) Ry(roll) Rx(pitch) (CONVENTIONS.md; w >= 0).
//   sensor_msgs/PointCloud2 of the markers (one point per marker triangulated
//       this frame, height 1, little endian, dense), per point (40 bytes):
//         x, y, z       FLOAT64 at 0, 8, 16   marker position in S, m
//         displacement  FLOAT64 at 24         |u_i|, the marker's displacement
//                                             from rest (contact field), m
//         id            UINT32  at 32         marker id (row * cols + col)
//         label         UINT8   at 36         0 outside the contact, 1 stick,
//                                             2 slip, 3 detached
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "onetip/types.hpp"

namespace onetip::pipeline {
struct FrameResult;
}

namespace onetip::dds {

struct RosTime {
  std::int32_t sec = 0;
  std::uint32_t nanosec = 0;
};
RosTime rosTime(double seconds);
double seconds(const RosTime& t);

std::array<float, 6> joyAxes(const Input6& v, const std::array<double, 6>& working_range);
// (x, y, z, w)
std::array<double, 4> quaternionXyzw(const Input6& v);
std::array<double, 3> positionMetres(const Input6& v);

struct CloudField {
  const char* name;
  std::uint32_t offset;
  std::uint8_t datatype;  // sensor_msgs/PointField constants
};
constexpr std::uint8_t kPointFieldUint8 = 2, kPointFieldUint32 = 6, kPointFieldFloat64 = 8;
constexpr std::uint32_t kMarkerPointStep = 40;
const std::array<CloudField, 6>& markerCloudFields();

struct MarkerCloud {
  std::uint32_t width = 0;          // points
  std::vector<std::uint8_t> data;   // width * kMarkerPointStep bytes
};
MarkerCloud markerCloud(const pipeline::FrameResult& r);

}  // namespace onetip::dds
