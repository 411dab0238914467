// pose/rigid_fit.hpp — closed-form least-squares rigid motion (Kabsch / Umeyama
// without scale), the paper's Eq. 1 under the full-stick assumption.
//
// Finds the proper rotation R and translation t minimising
//   sum_i w_i |R a_i + t - b_i|^2
// (points in S, mm): with centroids a_bar, b_bar and H = sum w_i (a_i - a_bar)(b_i - b_bar)^T
// = U S V^T, R = V diag(1, 1, det(V U^T)) U^T and t = b_bar - R a_bar.
// Degenerate when fewer than three points or all on one line (the second
// singular value of H below 1e-9 of the first): ok = false, motion = identity.
//
// Robust variant: iteratively reweighted with Cauchy weights
// w_i = 1 / (1 + (r_i / scale_mm)^2) of the previous fit's residuals r_i, so a
// few markers that do not follow the motion (slipping or out of contact but
// not yet labelled) barely pull the fit.
// Translation-only variant: t = weighted mean of b_i - a_i, R = I (for point
// sets too small or too narrow to fix a rotation).
// rotationSpread: the smaller principal RMS extent of the points' x-y
// projection (mm), i.e. how well they constrain a rotation.
#pragma once

#include <Eigen/Geometry>
#include <vector>

namespace onetip::pose {

struct RigidFit {
  bool ok = false;
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();  // maps `from` onto `to`
  double rms_mm = 0;  // weighted root-mean-square residual
};

// `weights` may be empty (all 1); otherwise one non-negative weight per point.
RigidFit fitRigidMotion(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to,
                        const std::vector<double>& weights = {});
RigidFit fitRigidMotionRobust(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to,
                              double scale_mm, int iterations = 2);
RigidFit fitTranslation(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to);
double rotationSpread(const std::vector<Eigen::Vector3d>& points);

}  // namespace onetip::pose
