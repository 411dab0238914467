// viewer/input_object.hpp — the 6-D input as a 3-D object that moves and turns
// with it (sensor frame S axes, mm).
//
// The object is a finger-shaped box (default 10 x 16 x 6 mm, long axis along
// S.y as the finger's) whose local origin is the centre of its lower face,
// resting on the pad plane z = 0 at zero input. Its model transform for the
// input [dx, dy, dz, yaw, pitch, roll] (mm, degrees) is
//   X -> R(yaw, pitch, roll) X + gain * (dx, dy, -dz)
// (R = Rz(yaw) Ry(roll) Rx(pitch), core/rotation.hpp; dz > 0 presses into the
// pad, so the box sinks; `gain` magnifies the few-mm translations).
// Face colours: lower (contact) face orange, upper grey, +-x red, +-y (tip)
// blue; the object's own axes x, y, z are drawn red, green, blue.
#pragma once

#include <Eigen/Geometry>

#include "onetip/types.hpp"
#include "viewer/vertex_formats.hpp"

namespace onetip::viewer {

Eigen::Isometry3d inputObjectPose(const Input6& input, double translation_gain);
MeshVertices fingerBox(const Eigen::Vector3d& size_mm);
PointVertices objectAxes(double length_mm);
// A square grid of lines on z = 0 from -half_extent to +half_extent.
PointVertices padGrid(double half_extent_mm, double step_mm);

}  // namespace onetip::viewer
