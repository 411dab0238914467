// input/pose_accumulator.hpp — the 6-D signal from per-frame increments.
//
// Given the finger's increments dT_k = T_k T_{k-1}^-1 (S, mm) since contact
// onset and the onset contact centroid c0:
//  - composed (proper SE(3)): T_k = dT_k ... dT_1, then the 6-D vector of
//    docs/reference.md, input6FromMotion(T_k, c0) (core/rotation.hpp);
//  - euler_sum (the paper's Sec. III-E): every increment turned into its own
//    6-D vector input6FromMotion(dT_k, c0) (Euler angle increments, the
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
  void reset(const Eigen::Vector3d& onset_centroid);
  void add(const Eigen::Isometry3d& increment);
  Input6 composed() const;
  Input6 eulerSum() const { return euler_sum_; }
  Input6 value(Accumulation a) const { return a == Accumulation::composed ? composed() : eulerSum(); }
  const Eigen::Isometry3d& motion() const { return motion_; }

 private:
  Eigen::Vector3d c0_{0, 0, 0};
  Eigen::Isometry3d motion_ = Eigen::Isometry3d::Identity();
  Input6 euler_sum_;
};

}  // namespace onetip::input
