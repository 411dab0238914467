// core/rotation.hpp — the rotation and 6-D input conventions of docs/reference.md.
//
// R = Rz(yaw) * Ry(roll) * Rx(pitch): yaw about S.z, roll about S.y (the
// finger's long axis), pitch about S.x, right-hand rule, angles in radians here.
// The 6-D vector of a rigid motion T (finger pose now relative to onset) at the
// onset contact centroid c0:  d = T(c0) - c0,  [dx, dy, dz] = [d.x, d.y, -d.z].
#pragma once

#include <Eigen/Geometry>

#include "onetip/types.hpp"

namespace onetip {

constexpr double kDegPerRad = 57.29577951308232;
constexpr double kRadPerDeg = 1.0 / kDegPerRad;

// Rotation matrix from yaw, pitch, roll in radians.
Eigen::Matrix3d rotationFromYawPitchRoll(double yaw, double pitch, double roll);

// Inverse of rotationFromYawPitchRoll: returns (yaw, pitch, roll) in radians,
// with roll in [-pi/2, pi/2]. Exact away from roll = +-90 deg (gimbal lock).
Eigen::Vector3d yawPitchRollFromRotation(const Eigen::Matrix3d& R);

// The 6-D input vector (angles in degrees) of the motion T at centroid c0.
Input6 input6FromMotion(const Eigen::Isometry3d& T, const Eigen::Vector3d& c0);

// The inverse of input6FromMotion: the rigid motion whose 6-D input at c0 is
// `input` (R from its angles, t = c0 + d - R c0 with d = [dx, dy, -dz]).
Eigen::Isometry3d motionFromInput6(const Input6& input, const Eigen::Vector3d& c0);

// A rigid motion from six pose parameters: translation (mm) and yaw, pitch,
// roll (radians), applied as X -> R * X + t.
Eigen::Isometry3d rigidFromTranslationYawPitchRoll(const Eigen::Vector3d& t, double yaw,
                                                   double pitch, double roll);

}  // namespace onetip
