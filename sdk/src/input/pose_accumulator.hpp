// input/pose_accumulator.hpp — the 6-D signal from per-frame increments.
//
// The estimator's increments dT_k = T_k T_{k-1}^-1 (S, mm) since contact onset
// are the motion of the marker layer. The markers lie d = marker_depth_mm below
// the contact surface and each moves with the surface point above it (m = s -
// d n, n = S.z out of the pad), so the finger's motion F, which carries the
// surface, is the markers' conjugated by that offset: F = D T D^-1 with D the
// translation by d n. F has T's rotation, and F moves c0 exactly as T moves
// c0 - d n: F(c0) - c0 = T(c0 - d n) - (c0 - d n). Without it a finger tilting
// by theta in stick reads d sin(theta) of slide (0.19 mm at 40 deg and 0.3 mm).
// Hence, with the onset contact centroid c0 and the reference point
// r = c0 - d n (per increment the same: conjugation commutes with composition):
//  - composed (proper SE(3)): T_k = dT_k ... dT_1, then the 6-D vector of
//    docs/reference.md, input6FromMotion(T_k, r) (core/rotation.hpp);
//  - euler_sum (the paper's Sec. III-E): every increment turned into its own
//    6-D vector input6FromMotion(dT_k, r) (Euler angle increments, the
//    displacement of c0) and those summed. Exact for motion about one fixed
//    axis; rotations about several axes do not commute, and a rotation that
//    moves the contact point away from c0 leaves later displacement
//    increments measured at the wrong point.
// Angles in degrees (user-facing), lengths in mm.
#pragma once

#include <Eigen/Geometry>

#include "onetip/types.hpp"

namespace onetip::input {

enum class Accumulation : std::uint8_t { composed = 0, euler_sum };

class PoseAccumulator {
 public:
  void reset(const Eigen::Vector3d& onset_centroid, double marker_depth_mm);
  void add(const Eigen::Isometry3d& increment);
  Input6 composed() const;
  Input6 eulerSum() const { return euler_sum_; }
  Input6 value(Accumulation a) const { return a == Accumulation::composed ? composed() : eulerSum(); }
  const Eigen::Isometry3d& motion() const { return motion_; }

 private:
  Eigen::Vector3d reference_{0, 0, 0};  // r = c0 - d n
  Eigen::Isometry3d motion_ = Eigen::Isometry3d::Identity();
  Input6 euler_sum_;
};

}  // namespace onetip::input
