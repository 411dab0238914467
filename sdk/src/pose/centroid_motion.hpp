// pose/centroid_motion.hpp — the macroscopic-slip fallback (paper Sec. III-D):
// when Eq. 16 fails the finger's motion from frame k-1 to k is taken to be the
// translation of the contact region's footprint centroid, c_k - c_{k-1}
// (S, mm), with no rotation. The footprint centroid (contact_field.hpp) weights
// each marker by how far its normal deformation exceeds the region cut, so it
// moves continuously with the pressure distribution rather than in steps of
// the marker spacing.
#pragma once

#include <Eigen/Geometry>

namespace onetip::pose {

inline Eigen::Isometry3d centroidMotion(const Eigen::Vector3d& centroid_before, const Eigen::Vector3d& centroid_now) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = centroid_now - centroid_before;
  return T;
}

}  // namespace onetip::pose
