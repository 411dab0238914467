#include "pose/pose_uncertainty.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>

#include "core/option_checks.hpp"
#include "core/rotation.hpp"

namespace onetip::pose {
namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

// S = diag(g, g, g, 1, 1, 1): scaled coordinates e_s = S e state turns as the arc length at radius g.
Matrix6d scaling(double g) {
  Matrix6d s = Matrix6d::Identity();
  s.topLeftCorner<3, 3>() *= g;
  return s;
}

}  // namespace

void PoseUncertaintyOptions::validate() const {
  requireInRange("pose uncertainty options: relative_increment_error", relative_increment_error, 0, 1, "");
  requireInRange("pose uncertainty options: unseen_turn_deg_per_sqrt_s", unseen_turn_deg_per_sqrt_s, 0, 1000,
                 "deg/sqrt(s)");
  requireInRange("pose uncertainty options: unseen_slide_mm_per_sqrt_s", unseen_slide_mm_per_sqrt_s, 0, 100,
                 "mm/sqrt(s)");
}

StickInformation stickInformation(const std::vector<Eigen::Vector3d>& points, const std::vector<double>& weights,
                                  const Eigen::Vector3d& centre, double sigma_mm, double fixed_sd_mm) {
  StickInformation out;
  double total = 0;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < points.size(); ++i) {
    total += weights[i];
    mean += weights[i] * points[i];
  }
  if (!(total > 0) || !(sigma_mm > 0)) return out;
  mean /= total;
  double spread = 0;
  Matrix6d h = Matrix6d::Zero();
  for (size_t i = 0; i < points.size(); ++i) {
    spread += weights[i] * (points[i] - mean).squaredNorm();
    Eigen::Matrix<double, 3, 6> j;
    j << -skew(points[i] - centre), Eigen::Matrix3d::Identity();
    h += weights[i] * j.transpose() * j;
  }
  h /= sigma_mm * sigma_mm * total;  // one marker's information at the set's spread (see the header)
  // A single point (or coincident ones) has no radius: its turns are unfixed at any scale, so 1 mm
  // keeps the scaled matrix defined. So is a set whose radius of gyration is within the marker noise
  // (weights that sit on one marker): scaled by such a radius, its turn would count as fixed to sigma / g
  // rad, without bound as g -> 0.
  const double gyration = std::sqrt(spread / total);
  const double g = gyration > sigma_mm ? gyration : 1.0;
  out.gyration_mm = g;
  const Matrix6d s_inv = scaling(g).inverse();
  const Eigen::SelfAdjointEigenSolver<Matrix6d> eig(s_inv * h * s_inv);
  Matrix6d fixed_scaled = Matrix6d::Zero();
  for (int k = 0; k < 6; ++k) {
    const double lambda = eig.eigenvalues()(k);
    if (!(lambda > 0) || 1.0 / std::sqrt(lambda) > fixed_sd_mm) continue;
    const Eigen::Matrix<double, 6, 1> v = eig.eigenvectors().col(k);
    fixed_scaled += v * v.transpose() / lambda;
    out.unfixed_projector -= v * v.transpose();
    ++out.fixed_directions;
  }
  out.fixed_covariance = s_inv * fixed_scaled * s_inv;
  return out;
}

PoseUncertainty::PoseUncertainty(PoseUncertaintyOptions options) : options_(options) { options_.validate(); }

void PoseUncertainty::reset(const Eigen::Vector3d& c0) {
  chain_.setZero();
  p_.setZero();
  c_ = c0;
}

void PoseUncertainty::add(const StickInformation& stick, const Eigen::Isometry3d& increment, double dt_s) {
  // Carried to the new point c' = dT c: the error turns with the increment and needs no other term.
  Matrix6d ad = Matrix6d::Zero();
  ad.topLeftCorner<3, 3>() = increment.linear();
  ad.bottomRightCorner<3, 3>() = increment.linear();
  const Eigen::Vector3d c_next = increment * c_;
  const double turn = Eigen::AngleAxisd(increment.linear()).angle();
  const double f = options_.relative_increment_error;
  Matrix6d q = Matrix6d::Zero();
  q.topLeftCorner<3, 3>().diagonal().setConstant(f * f * turn * turn);
  q.bottomRightCorner<3, 3>().diagonal().setConstant(f * f * (c_next - c_).squaredNorm());
  // The motion prior's random walk in the directions the stick set does not fix.
  const double q_turn = options_.unseen_turn_deg_per_sqrt_s * kRadPerDeg, q_slide = options_.unseen_slide_mm_per_sqrt_s;
  Matrix6d prior = Matrix6d::Zero();
  prior.topLeftCorner<3, 3>().diagonal().setConstant(q_turn * q_turn * dt_s);
  prior.bottomRightCorner<3, 3>().diagonal().setConstant(q_slide * q_slide * dt_s);
  if (stick.fixed_directions > 0) {
    const Matrix6d s = scaling(stick.gyration_mm), s_inv = s.inverse();
    prior = s_inv * stick.unfixed_projector * s * prior * s * stick.unfixed_projector * s_inv;
  }
  chain_ = ad * chain_ * ad.transpose() + q + prior;
  // The fit's own noise is the error of this frame's solve against the anchors; it does not accumulate.
  p_ = chain_ + stick.fixed_covariance;
  c_ = c_next;
}

Input6 PoseUncertainty::sd() const {
  const auto s = [&](int k) { return std::sqrt(std::max(0.0, p_(k, k))); };
  return {s(3), s(4), s(5), s(2) * kDegPerRad, s(0) * kDegPerRad, s(1) * kDegPerRad};
}

}  // namespace onetip::pose
