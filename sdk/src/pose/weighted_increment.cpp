#include "pose/weighted_increment.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>

#include "pose/truncated_least_squares.hpp"

namespace onetip::pose {

namespace {

using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;
using Row6 = Eigen::Matrix<double, 1, 6>;

Eigen::Matrix3d skew(const Eigen::Vector3d& u) {
  Eigen::Matrix3d s;
  s << 0, -u.z(), u.y(), u.z(), 0, -u.x(), -u.y(), u.x(), 0;
  return s;
}

struct Increment {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d v{0, 0, 0};
  Eigen::Vector3d apply(const Eigen::Vector3d& q, const Eigen::Vector3d& c) const { return R * (q - c) + c + v; }
};

// d(dT(q)) / d[dtheta; dv] at the current dT: [-[R(q - c)]x, I].
Eigen::Matrix<double, 3, 6> pointJacobian(const Increment& inc, const Eigen::Vector3d& q, const Eigen::Vector3d& c) {
  Eigen::Matrix<double, 3, 6> j;
  j.leftCols<3>() = -skew(inc.R * (q - c));
  j.rightCols<3>() = Eigen::Matrix3d::Identity();
  return j;
}

double surfaceSd(const WeightedMarker& m) { return m.surface_sd_mm > 0 ? m.surface_sd_mm : m.sd_mm; }

}  // namespace

Eigen::Isometry3d solveWeightedIncrement(const WeightedIncrementProblem& p, const Eigen::Isometry3d& initial,
                                         WeightedResiduals* residuals, int iterations) {
  const Eigen::Vector3d& c = p.centre;
  Increment inc;
  inc.R = initial.linear();
  inc.v = initial * c - c;
  const double n = std::max<double>(1.0, static_cast<double>(p.markers.size()));
  for (int it = 0; it < iterations; ++it) {
    Matrix6d H = Matrix6d::Zero();
    Vector6d g = Vector6d::Zero();
    for (const WeightedMarker& m : p.markers) {
      const double marker_info = 1.0 / (n * m.sd_mm * m.sd_mm);
      if (m.weight > 0) {
        const Eigen::Matrix<double, 3, 6> J = pointJacobian(inc, m.anchor, c);
        const Eigen::Vector3d e = inc.apply(m.anchor, c) - m.now;
        H += m.weight * marker_info * J.transpose() * J;
        g += m.weight * marker_info * J.transpose() * e;
      }
      const double slip_weight = (1 - m.weight) * m.on_surface;
      if (slip_weight > 0 && m.normal.squaredNorm() > 0) {
        const Row6 J = m.normal.transpose() * pointJacobian(inc, m.before, c);
        const double e = m.normal.dot(inc.apply(m.before, c) - m.now);
        const double surface_info = 1.0 / (n * surfaceSd(m) * surfaceSd(m));
        H += slip_weight * surface_info * J.transpose() * J;
        g += slip_weight * surface_info * J.transpose() * e;
      }
    }
    if (p.footprint) {
      const double info = 1.0 / (p.footprint->sd_mm * p.footprint->sd_mm);
      const Eigen::Matrix<double, 2, 6> J = pointJacobian(inc, p.footprint->carried, c).topRows<2>();
      const Eigen::Vector2d e = (inc.apply(p.footprint->carried, c) - p.footprint->seen).head<2>();
      H += info * J.transpose() * J;
      g += info * J.transpose() * e;
    }
    // The prior: the increment's turn and slide about the expected ones (zero: the motion held).
    const Eigen::AngleAxisd turn(inc.R);
    const double turn_info = 1.0 / (p.prior_turn_sd_rad * p.prior_turn_sd_rad);
    const double slide_info = 1.0 / (p.prior_slide_sd_mm * p.prior_slide_sd_mm);
    H.topLeftCorner<3, 3>() += turn_info * Eigen::Matrix3d::Identity();
    g.head<3>() += turn_info * (turn.angle() * turn.axis() - p.prior_turn_rad);
    H.bottomRightCorner<3, 3>() += slide_info * Eigen::Matrix3d::Identity();
    g.tail<3>() += slide_info * (inc.v - p.prior_slide_mm);
    const Vector6d step = -H.ldlt().solve(g);
    if (!step.allFinite()) break;
    const Eigen::Vector3d dtheta = step.head<3>();
    if (dtheta.norm() > 0) inc.R = Eigen::AngleAxisd(dtheta.norm(), dtheta.normalized()).toRotationMatrix() * inc.R;
    inc.v += step.tail<3>();
    if (step.norm() < 1e-9) break;
  }
  if (residuals) {
    residuals->stick.clear();
    residuals->normal.clear();
    for (const WeightedMarker& m : p.markers) {
      residuals->stick.push_back((inc.apply(m.anchor, c) - m.now) / m.sd_mm);
      residuals->normal.push_back(m.normal.dot(inc.apply(m.before, c) - m.now) / surfaceSd(m));
    }
  }
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = inc.R;
  out.translation() = c + inc.v - inc.R * c;
  return out;
}

bool leadsTheFinger(const WeightedMarker& marker, const Eigen::Vector3d& residual) {
  constexpr double kLeadBound = 2.576;  // sqrt(chi2_1(0.99)): one component of noise
  return -residual.dot(marker.from_rest) > kLeadBound;
}

double stickWeight(const WeightedMarker& marker, const Eigen::Vector3d& residual, double cbar2, double mu) {
  if (leadsTheFinger(marker, residual)) return 1.0;
  const double r2 = residual.squaredNorm();
  if (std::isinf(mu)) return r2 <= cbar2 ? 1.0 : 0.0;
  return gncWeight(r2, cbar2, mu);
}

namespace {

// The cheapest case of each marker at residuals r (truncatedCost), as weights; returns whether any changed.
bool takeCheapestCases(WeightedIncrementProblem& problem, const WeightedResiduals& r) {
  const double truncated = std::numeric_limits<double>::infinity();
  bool changed = false;
  for (size_t i = 0; i < r.stick.size(); ++i) {
    WeightedMarker& m = problem.markers[i];
    const double w = stickWeight(m, r.stick[i], kStickChi2, truncated);
    const double v = r.normal[i] * r.normal[i] <= kSurfaceChi2 ? 1.0 : 0.0;
    changed |= w != m.weight || v != m.on_surface;
    m.weight = w;
    m.on_surface = v;
  }
  return changed;
}

}  // namespace

double truncatedCost(const WeightedIncrementProblem& p, const Eigen::Isometry3d& dT) {
  const Eigen::Vector3d& c = p.centre;
  double markers = 0;
  for (const WeightedMarker& m : p.markers) {
    const Eigen::Vector3d e = (dT * m.anchor - m.now) / m.sd_mm;
    const double nu = m.normal.dot(dT * m.before - m.now) / surfaceSd(m);
    const double slips = kStickChi2 + std::min(nu * nu, kSurfaceChi2);
    markers += leadsTheFinger(m, e) ? e.squaredNorm() : std::min(e.squaredNorm(), slips);
  }
  double cost = p.markers.empty() ? 0.0 : markers / static_cast<double>(p.markers.size());
  if (p.footprint)
    cost += ((dT * p.footprint->carried - p.footprint->seen).head<2>() / p.footprint->sd_mm).squaredNorm();
  const Eigen::AngleAxisd turn(dT.linear());
  cost += ((turn.angle() * turn.axis() - p.prior_turn_rad) / p.prior_turn_sd_rad).squaredNorm() +
          ((dT * c - c - p.prior_slide_mm) / p.prior_slide_sd_mm).squaredNorm();
  return cost;
}

Eigen::Isometry3d solveByReweighting(WeightedIncrementProblem& problem, const Eigen::Isometry3d& initial) {
  constexpr int kRounds = 10;  // the cases settle in 2-4 rounds
  WeightedResiduals r;
  Eigen::Isometry3d dT = solveWeightedIncrement(problem, initial, &r);
  for (int round = 0; round < kRounds && takeCheapestCases(problem, r); ++round)
    dT = solveWeightedIncrement(problem, dT, &r);
  return dT;
}

Eigen::Isometry3d solveByGraduatedNonConvexity(WeightedIncrementProblem& problem, const Eigen::Isometry3d& initial) {
  constexpr double kGrowth = 1.4;  // mu's growth per round (Yang et al. 2020)
  constexpr int kRounds = 60;      // mu grows by 1.4^60: far past binary weights
  for (WeightedMarker& m : problem.markers) m.weight = 1;
  WeightedResiduals r;
  Eigen::Isometry3d dT = solveWeightedIncrement(problem, initial, &r);
  double max_r2 = 0;
  for (const Eigen::Vector3d& e : r.stick) max_r2 = std::max(max_r2, e.squaredNorm());
  double mu = gncInitialMu(max_r2, kStickChi2);
  std::vector<double> w(r.stick.size());
  for (int round = 0; round < kRounds && mu > 0; ++round, mu *= kGrowth) {
    for (size_t i = 0; i < w.size(); ++i)
      w[i] = problem.markers[i].weight = stickWeight(problem.markers[i], r.stick[i], kStickChi2, mu);
    dT = solveWeightedIncrement(problem, dT, &r);
    if (gncWeightsBinary(w)) break;
  }
  return solveByReweighting(problem, dT);
}

}  // namespace onetip::pose
