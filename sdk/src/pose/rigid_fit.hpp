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
// Trimmed variant (for a set that may still hold a few undetected slipping
// markers): the least-squares fit is repeated without one point while some
// residual r_i = b_i - (R a_i + t) exceeds trim_mm and more than three points
// remain; the points kept are the inliers, and the result is the robust fit
// over them. (Least squares while trimming: a robust fit may lock onto a
// large slipping group and leave nothing to tell the groups apart.) Which point goes: the largest residual
// among those that point back towards their rest position
// (r_i . relax_i > 0, relax_i given per point, e.g. minus the marker's
// tangential displacement: an elastic skin slips back towards rest relative
// to the finger, it is never dragged ahead of it), else the largest residual.
// One point at a time, and the direction, matter: a ring of slipping markers
// drags the first fit so far that the sticking markers inside it show
// residuals as large as the ring's (a rotation fit weighs points by their
// squared distance), but ahead of the fit instead of behind it.
// Translation-only variant: t = weighted mean of b_i - a_i, R = I (for point
// sets too small or too narrow to fix a rotation).
// Rotation about S.z only (for points along a line, which fix the rotation
// about the pad normal but not about the line): R = Rz(theta) with theta from
// the 2-D Procrustes problem on the centred x-y coordinates,
// theta = atan2(sum a x b, sum a . b), and t = b_bar - R a_bar.
// planarSpread: the (smaller, larger) principal RMS extents of the points'
// x-y projection (mm), i.e. how well they constrain a general rotation and a
// rotation about S.z; planarExtent also gives the direction of the larger
// (the line a thin set lies along: the axis it fixes a turn about worst).
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
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
struct TrimmedFit {
  RigidFit fit;
  std::vector<std::uint8_t> inlier;  // per point: kept in the final fit
  bool within_trim = false;          // every kept point's least-squares residual is within trim_mm
};
// `relax` may be empty (no direction preferred). Trimming also stops once
// `min_kept` points remain (a caller that needs that many stops paying for
// refits that cannot succeed; within_trim then tells whether they sufficed).
TrimmedFit fitRigidMotionTrimmed(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to,
                                 const std::vector<Eigen::Vector3d>& relax, double scale_mm, double trim_mm,
                                 size_t min_kept = 0);
RigidFit fitTranslation(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to);
RigidFit fitRotationAboutZ(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to);
struct PlanarExtent {
  Eigen::Vector2d spread = Eigen::Vector2d::Zero();        // (smaller, larger) RMS extents (mm)
  Eigen::Vector2d major_axis = Eigen::Vector2d::UnitX();   // unit, S.xy, along the larger
};
PlanarExtent planarExtent(const std::vector<Eigen::Vector3d>& points);
Eigen::Vector2d planarSpread(const std::vector<Eigen::Vector3d>& points);

}  // namespace onetip::pose
