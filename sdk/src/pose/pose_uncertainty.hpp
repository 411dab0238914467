// pose/pose_uncertainty.hpp — how well the finger's motion since onset is
// known, axis by axis, and which directions the contact cannot fix.
//
// The error of the pose T_k is a small motion e = [dtheta; dt] (rad; mm)
// applied at the moving reference point c_k = T_k(c0): dtheta the turn
// (about S.x, S.y, S.z), dt the displacement of c_k. Its covariance P (6x6)
// is carried from frame to frame like an odometer's (the pose is a chain of
// increments T_k = dT_k T_{k-1}):
//   P_k = A P_{k-1} A^T + Q_k,   A = [I 0; -[c_k - c_{k-1}]x I]
// (A moves the point the error is stated at: dt' = dt + dtheta x (c_k - c_{k-1})).
//
// Q_k, this frame's increment error, from the stick set (markers q_i, S, mm,
// with weights w_i in [0, 1]) and its residual spread sigma (per axis, mm):
//  - its information about e is H = sum_i w_i J_i^T J_i / (sigma^2 sum_i w_i)
//    with J_i = [-[q_i - c_k]x, I] (a turn moves q_i by dtheta x (q_i - c_k)).
//    The residuals of a stick set about its rigid fit are mostly the marker
//    layer's own smooth deformation, common to neighbouring markers, not
//    independent noise; so the set is credited with the information of one
//    marker at its spread, not n: averaging does not remove a shared error
//    (on the shipped press the turn is 0.03 deg off from the first frames on,
//    where sigma^2 / n would claim 0.009 deg);
//  - scaled by the set's radius of gyration g (g^2 = mean_w |q_i - q_bar|^2),
//    S = diag(g, g, g, 1, 1, 1), Hs = S^-1 H S^-1 compares mm with mm. Its
//    eigen-directions v_j with 1/sqrt(lambda_j) <= fixed_sd_mm are fixed by
//    the markers (the set's own error there is 1/lambda_j); the others are
//    not (a thin set does not fix the turn about its own line, an empty set
//    fixes nothing) and take the motion prior's: variance growing as a random
//    walk, q_turn^2 dt in each turn and q_slide^2 dt in each displacement;
//  - the increment's model error (a marker layer that does not follow the
//    finger rigidly, a slip missed for a frame) scales with the increment,
//    as an odometer's: (f |dtheta_k|)^2 and (f |dc_k|)^2 on every axis, f
//    the relative increment error.
// The standard deviations are sqrt(diag P): dx, dy, dz from dt (mm), yaw
// from the turn about S.z, pitch about S.x, roll about S.y (deg; exact to
// first order about the upright finger, which is what the Euler angles of
// docs/reference.md reduce to for small errors).
//
// Why not Ceres' covariance: its pseudo-inverse reports zero variance in the
// directions nobody can see; here those grow with time as the prior says.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "onetip/types.hpp"

namespace onetip::pose {

struct PoseUncertaintyOptions {
  double relative_increment_error = 0.05;  // [0, 1] f: sd of an increment's error per unit of its size
  double unseen_turn_deg_per_sqrt_s = 10;  // [0, 1000] q_turn: random walk of a turn no marker fixes
  double unseen_slide_mm_per_sqrt_s = 5;   // [0, 100] q_slide: random walk of a displacement no marker fixes
  void validate() const;                   // throws InputError naming the bad field
};

using Matrix6d = Eigen::Matrix<double, 6, 6>;

// Which directions a weighted stick set fixes, and how well (see above).
struct StickInformation {
  Matrix6d fixed_covariance = Matrix6d::Zero();  // [dtheta; dt] of the fixed directions (rad, mm)
  Matrix6d unfixed_projector = Matrix6d::Identity();  // onto the unfixed directions, in scaled coordinates
  double gyration_mm = 1;                        // g (1 mm for a set without extent: its turns are unfixed)
  int fixed_directions = 0;                      // 0..6
};

// `points` (S, mm) with `weights` in [0, 1] (equal sizes); sigma_mm > 0 the
// per-axis spread of a sticking marker about the fit; fixed_sd_mm > 0.
StickInformation stickInformation(const std::vector<Eigen::Vector3d>& points, const std::vector<double>& weights,
                                  const Eigen::Vector3d& centre, double sigma_mm, double fixed_sd_mm);

class PoseUncertainty {
 public:
  explicit PoseUncertainty(PoseUncertaintyOptions options = {});
  // At contact onset: the pose is the identity, known exactly, at point c0.
  void reset(const Eigen::Vector3d& c0);
  // One frame: the stick set's information (stickInformation, about the new
  // reference point pose * c0), the increment dT_k and the frame interval (s).
  void add(const StickInformation& stick, const Eigen::Isometry3d& increment, double dt_s);
  const Matrix6d& covariance() const { return p_; }
  Input6 sd() const;  // mm, deg

 private:
  PoseUncertaintyOptions options_;
  Matrix6d chain_ = Matrix6d::Zero();  // accumulated over the increments (model error and prior)
  Matrix6d p_ = Matrix6d::Zero();      // chain_ plus this frame's fit noise
  Eigen::Vector3d c_{0, 0, 0};
};

}  // namespace onetip::pose
