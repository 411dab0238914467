// pose/contact_snapshot.hpp — what the pose estimator keeps of one frame of a
// contact, and how two such frames' footprints are compared.
//
// The footprint tests (pose/adaptive_pose_estimator.hpp) compare the frame
// k-w of their window with frame k. Both footprint centres
// (contact/footprint_centre.hpp) are taken over the same lattice cells: those
// of either frame's region measured in both frames, and each cell at or beside
// them that is not measured in one frame or both (hidden for good, or lost),
// read in both frames as its neighbours' interpolant (contact/lattice_hole.hpp).
// A marker lost or found moves neither centre, and a dimple sliding past a
// hole is not pulled away from it. Over the same cells, the sums of the normal
// deformation n_i = -u_i.z (mm) say how much deeper the press has become.
// Positions in the sensor frame S, mm.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "contact/contact_field.hpp"
#include "core/marker_field.hpp"

namespace onetip::pose {

struct ContactSnapshot {
  MarkerField markers;                        // measured (S, mm)
  std::vector<Eigen::Vector3d> displacement;  // u_i from the contact field (mm)
  double cut_mm = 0;                          // the tracked region's cut (ContactRegion::cut_mm, mm)
  std::vector<int> members;                   // of the tracked region
  Eigen::Vector3d footprint{0, 0, 0};         // the tracked region's footprint centre (S, mm)
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // the estimate T at that frame
  double region_size = 0;                     // markers in the tracked region
};

struct CommonFootprints {
  Eigen::Vector3d before{0, 0, 0}, after{0, 0, 0};  // footprint centres (S, mm)
  double depth_before = 0, depth_after = 0;         // sums of n_i over the common markers (mm)
};

// `before` against the current frame (`field`, its tracked region's `members`,
// the measured markers `now`). With no common marker both centres are
// before.footprint and both sums zero.
CommonFootprints commonFootprints(const ContactSnapshot& before, const contact::ContactField& field,
                                  const std::vector<int>& members, const MarkerField& now);

}  // namespace onetip::pose
