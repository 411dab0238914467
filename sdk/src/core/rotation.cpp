#include "core/rotation.hpp"

#include <algorithm>
#include <cmath>

namespace onetip {

Eigen::Matrix3d rotationFromYawPitchRoll(double yaw, double pitch, double roll) {
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Vector3d yawPitchRollFromRotation(const Eigen::Matrix3d& R) {
  // R = Rz(a) Ry(b) Rx(c): R(2,0) = -sin b, R(2,1) = cos b sin c,
  // R(2,2) = cos b cos c, R(1,0) = sin a cos b, R(0,0) = cos a cos b.
  const double s = std::clamp(-R(2, 0), -1.0, 1.0);
  const double roll = std::asin(s);
  const double pitch = std::atan2(R(2, 1), R(2, 2));
  const double yaw = std::atan2(R(1, 0), R(0, 0));
  return {yaw, pitch, roll};
}

Input6 input6FromMotion(const Eigen::Isometry3d& T, const Eigen::Vector3d& c0) {
  const Eigen::Vector3d d = T * c0 - c0;
  const Eigen::Vector3d ypr = yawPitchRollFromRotation(T.linear());
  return {d.x(), d.y(), -d.z(), ypr[0] * kDegPerRad, ypr[1] * kDegPerRad, ypr[2] * kDegPerRad};
}

Eigen::Isometry3d motionFromInput6(const Input6& input, const Eigen::Vector3d& c0) {
  const Eigen::Matrix3d R =
      rotationFromYawPitchRoll(input.yaw * kRadPerDeg, input.pitch * kRadPerDeg, input.roll * kRadPerDeg);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = R;
  T.translation() = c0 + Eigen::Vector3d(input.dx, input.dy, -input.dz) - R * c0;
  return T;
}

Eigen::Isometry3d rigidFromTranslationYawPitchRoll(const Eigen::Vector3d& t, double yaw,
                                                   double pitch, double roll) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = rotationFromYawPitchRoll(yaw, pitch, roll);
  T.translation() = t;
  return T;
}

}  // namespace onetip
