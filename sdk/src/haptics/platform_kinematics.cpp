#include "haptics/platform_kinematics.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/rotation.hpp"

namespace onetip::haptics {

void PlatformGeometry::validate() const {
  if (!(pulley_radius_mm > 0.0 && pulley_radius_mm < 50.0))
    throw InputError("PlatformGeometry.pulley_radius_mm: must be in (0, 50)");
  if (!(vertex_radius_mm > 0.0 && vertex_radius_mm < 100.0))
    throw InputError("PlatformGeometry.vertex_radius_mm: must be in (0, 100)");
  if (!(rest_gap_mm >= 0.0 && rest_gap_mm < 50.0)) throw InputError("PlatformGeometry.rest_gap_mm: must be in [0, 50)");
}

std::array<double, 3> clampServoAngles(const std::array<double, 3>& degrees) {
  std::array<double, 3> out{};
  for (size_t i = 0; i < 3; ++i) out[i] = std::clamp(degrees[i], kServoMinDeg, kServoMaxDeg);
  return out;
}

PlatformKinematics::PlatformKinematics(const PlatformGeometry& geometry) : geometry_(geometry) {
  geometry_.validate();
  const std::array<double, 3> angles = {90.0, -30.0, 210.0};
  for (size_t i = 0; i < 3; ++i)
    xy_[i] = geometry_.vertex_radius_mm *
             Eigen::Vector2d(std::cos(angles[i] * kRadPerDeg), std::sin(angles[i] * kRadPerDeg));
}

Eigen::Vector3d PlatformKinematics::vertex(int i, const std::array<double, 3>& degrees) const {
  const auto m = clampServoAngles(degrees);
  const auto k = static_cast<size_t>(i);
  const double h = -geometry_.rest_gap_mm + geometry_.pulley_radius_mm * (m[k] - kServoMinDeg) * kRadPerDeg;
  return {xy_[k].x(), xy_[k].y(), h};
}

PlatformPose PlatformKinematics::forward(const std::array<double, 3>& degrees) const {
  Eigen::Matrix3d A;
  Eigen::Vector3d h;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d v = vertex(i, degrees);
    A.row(i) << 1.0, v.x(), v.y();
    h(i) = v.z();
  }
  const Eigen::Vector3d zab = A.lu().solve(h);  // z = z_c + a x + b y
  PlatformPose pose;
  pose.z_mm = zab(0);
  pose.plane.point = Eigen::Vector3d(0.0, 0.0, zab(0));
  pose.plane.normal = Eigen::Vector3d(-zab(1), -zab(2), 1.0).normalized();
  pose.pitch_deg = -std::asin(pose.plane.normal.y()) * kDegPerRad;
  pose.roll_deg = std::atan2(pose.plane.normal.x(), pose.plane.normal.z()) * kDegPerRad;
  return pose;
}

}  // namespace onetip::haptics
