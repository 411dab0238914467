// core/sensor_frame.hpp — the sensor frame S, derived from the rest markers.
//
// docs/reference.md: origin at the centroid of the rest-state 3-D markers; z the
// normal of their least-squares plane, pointing away from the camera; x the
// direction of increasing column index projected onto that plane; y = z × x.
// Input markers are in the left camera frame L (camera at the origin), so
// "away from the camera" means z · centroid > 0.
#pragma once

#include <Eigen/Geometry>

#include "core/marker_field.hpp"

namespace onetip {

class SensorFrame {
 public:
  SensorFrame() = default;
  // Fits S to the valid rest markers (in L). Throws InputError when fewer than
  // 3 non-collinear markers or no two markers along a row are valid.
  static SensorFrame fromRestMarkers(const MarkerField& rest_in_L);
  // S from an explicit transform (X_S = S_from_L * X_L).
  explicit SensorFrame(const Eigen::Isometry3d& S_from_L) : S_from_L_(S_from_L) {}

  const Eigen::Isometry3d& sensorFromLeft() const noexcept { return S_from_L_; }
  Eigen::Vector3d toSensor(const Eigen::Vector3d& X_L) const { return S_from_L_ * X_L; }
  MarkerField toSensor(const MarkerField& in_L) const;

 private:
  Eigen::Isometry3d S_from_L_ = Eigen::Isometry3d::Identity();
};

}  // namespace onetip
