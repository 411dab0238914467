// The one-objective increment (pose/weighted_increment.hpp) and its stick
// weights (pose/truncated_least_squares.hpp) on exact synthetic motions.
#include <gtest/gtest.h>

#include <random>

#include "core/rotation.hpp"
#include "pose/rigid_fit.hpp"
#include "pose/truncated_least_squares.hpp"
#include "pose/weighted_increment.hpp"

using namespace onetip;
using namespace onetip::pose;

namespace {

std::vector<Eigen::Vector3d> patch(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-3, 3);
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < n; ++i) p.emplace_back(u(rng), u(rng), 0.2 * u(rng));
  return p;
}

WeightedIncrementProblem problemFor(const std::vector<Eigen::Vector3d>& a, const Eigen::Isometry3d& T) {
  WeightedIncrementProblem p;
  p.prior_turn_sd_rad = 1e3;  // a prior too weak to matter
  p.prior_slide_sd_mm = 1e3;
  for (const auto& q : a) p.markers.push_back({q, q, T * q, Eigen::Vector3d::UnitZ(), 1.0, 0.001});
  return p;
}

double turnBetween(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}

}  // namespace

TEST(WeightedIncrement, EveryMarkerStickingIsKabsch) {
  std::mt19937 rng(5);
  const auto a = patch(25, rng);
  const Eigen::Isometry3d T = rigidFromTranslationYawPitchRoll({0.05, -0.03, 0.02}, 0.02, -0.015, 0.01);
  std::vector<Eigen::Vector3d> b;
  std::normal_distribution<double> noise(0, 0.0005);
  for (const auto& q : a) b.push_back(T * q + Eigen::Vector3d(noise(rng), noise(rng), noise(rng)));
  WeightedIncrementProblem p = problemFor(a, T);
  for (size_t i = 0; i < a.size(); ++i) p.markers[i].now = b[i];
  const Eigen::Isometry3d got = solveWeightedIncrement(p, Eigen::Isometry3d::Identity(), nullptr, 5);
  const RigidFit reference = fitRigidMotion(a, b);
  ASSERT_TRUE(reference.ok);
  EXPECT_LT(turnBetween(got, reference.motion), 1e-7);
  EXPECT_LT((got.translation() - reference.motion.translation()).norm(), 1e-6);
}

TEST(WeightedIncrement, WithNoMarkerStickingTheFootprintCarriesTheSlide) {
  std::mt19937 rng(6);
  const auto a = patch(20, rng);
  // The finger slides 0.2 mm in x; its markers stay behind (they slip) and stay on the flat surface.
  WeightedIncrementProblem p = problemFor(a, Eigen::Isometry3d::Identity());
  for (auto& m : p.markers) m.weight = 0;
  p.footprint = FootprintEvidence{{0, 0, 0}, {0.2, 0, 0}, 0.01};
  p.prior_turn_sd_rad = 0.01;
  const Eigen::Isometry3d got = solveWeightedIncrement(p, Eigen::Isometry3d::Identity());
  EXPECT_NEAR(got.translation().x(), 0.2, 1e-6);
  EXPECT_NEAR(got.translation().y(), 0.0, 1e-6);
  EXPECT_NEAR(got.translation().z(), 0.0, 1e-6);  // the normal residuals hold the depth
  EXPECT_LT(Eigen::AngleAxisd(got.linear()).angle(), 1e-6);
}

TEST(WeightedIncrement, WithNothingSeenThePriorHoldsTheMotion) {
  WeightedIncrementProblem p;
  const Eigen::Isometry3d start = rigidFromTranslationYawPitchRoll({0.3, 0.1, -0.2}, 0.1, 0.05, -0.02);
  const Eigen::Isometry3d got = solveWeightedIncrement(p, start, nullptr, 10);
  EXPECT_LT(Eigen::AngleAxisd(got.linear()).angle(), 1e-9);
  EXPECT_LT(got.translation().norm(), 1e-9);
}

TEST(WeightedIncrement, WithNothingSeenAPriorWithARateExpectsItsIncrement) {
  // The prior's expected turn theta_p and move of c, v_p: with no evidence the solve returns exactly that
  // increment about c, at no cost; evidence pulls it away in the directions it fixes.
  WeightedIncrementProblem p;
  p.centre = {0.5, -0.2, 8.0};
  p.prior_turn_rad = Eigen::Vector3d(0.01, -0.02, 0.03);
  p.prior_slide_mm = Eigen::Vector3d(0.05, 0.0, -0.01);
  p.prior_turn_sd_rad = 0.01;
  p.prior_slide_sd_mm = 0.01;
  const Eigen::Isometry3d got = solveWeightedIncrement(p, Eigen::Isometry3d::Identity(), nullptr, 10);
  const Eigen::AngleAxisd turn(got.linear());
  EXPECT_LT((turn.angle() * turn.axis() - p.prior_turn_rad).norm(), 1e-9);
  EXPECT_LT((got * p.centre - p.centre - p.prior_slide_mm).norm(), 1e-9);
  EXPECT_NEAR(truncatedCost(p, got), 0.0, 1e-12);
  EXPECT_GT(truncatedCost(p, Eigen::Isometry3d::Identity()), 1.0);  // holding the motion now costs
}

TEST(WeightedIncrement, ResidualsAreReportedInUnitsOfTheirSd) {
  std::mt19937 rng(7);
  const auto a = patch(5, rng);
  WeightedIncrementProblem p = problemFor(a, Eigen::Isometry3d::Identity());
  p.markers[2].now += Eigen::Vector3d(0.003, 0, 0.004);  // 5 sd off, 4 sd along the normal
  p.markers[2].weight = 0;
  p.markers[2].on_surface = 0;  // it enters neither term: its residuals are the offsets above
  WeightedResiduals r;
  solveWeightedIncrement(p, Eigen::Isometry3d::Identity(), &r, 5);
  EXPECT_NEAR(r.stick[2].squaredNorm(), 25.0, 0.5);
  EXPECT_NEAR(r.normal[2] * r.normal[2], 16.0, 0.5);
  EXPECT_LT(r.stick[0].squaredNorm(), 1.0);
}

TEST(TruncatedLeastSquares, GncWeightsGraduateFromLeastSquaresToTheTruncatedCost) {
  const double c2 = 1.0;
  // mu_0 keeps the largest residual of the first solve inside the surrogate's convex part.
  const double max_r2 = 50.0;
  const double mu0 = gncInitialMu(max_r2, c2);
  EXPECT_GT(gncWeight(max_r2, c2, mu0), 0.0);
  EXPECT_EQ(gncInitialMu(0.5, c2), 0.0);  // every residual within the bound: nothing to graduate
  // Continuous across both interval ends, and 1 / 0 beyond them.
  for (double mu : {0.01, 0.3, 1.0, 10.0}) {
    const double lo = mu / (mu + 1) * c2, hi = (mu + 1) / mu * c2;
    EXPECT_NEAR(gncWeight(lo * (1 + 1e-9), c2, mu), 1.0, 1e-6);
    EXPECT_NEAR(gncWeight(hi * (1 - 1e-9), c2, mu), 0.0, 1e-6);
    EXPECT_EQ(gncWeight(0.5 * lo, c2, mu), 1.0);
    EXPECT_EQ(gncWeight(2 * hi, c2, mu), 0.0);
    double previous = 1.0;  // non-increasing in the residual
    for (double r2 = lo; r2 <= hi; r2 += (hi - lo) / 20) {
      const double w = gncWeight(r2, c2, mu);
      EXPECT_LE(w, previous + 1e-12);
      previous = w;
    }
  }
  // At large mu the weights are the truncated cost's: inside the bound or not.
  EXPECT_EQ(gncWeight(0.99, c2, 1e6), 1.0);
  EXPECT_EQ(gncWeight(1.01, c2, 1e6), 0.0);
  EXPECT_TRUE(gncWeightsBinary({0.0, 1.0, 0.9999}));
  EXPECT_FALSE(gncWeightsBinary({0.0, 0.5}));
}

TEST(TruncatedLeastSquares, GncFindsTheStickingMajorityFromEveryMarkerSticking) {
  std::mt19937 rng(8);
  const auto a = patch(30, rng);
  const Eigen::Isometry3d T = rigidFromTranslationYawPitchRoll({0.04, 0.02, -0.03}, 0.03, 0.01, -0.02);
  WeightedIncrementProblem p = problemFor(a, T);
  std::normal_distribution<double> noise(0, 0.0005);
  for (auto& m : p.markers) m.now += Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
  // 40 % slip: a rim left behind by the finger, but pressed with it (they stay on its surface).
  for (size_t i = 0; i < 12; ++i) p.markers[i].now = a[i] + (T * a[i] - a[i]).z() * Eigen::Vector3d::UnitZ();
  const Eigen::Isometry3d dT = solveByGraduatedNonConvexity(p, Eigen::Isometry3d::Identity());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(p.markers[i].weight > 0.5, i >= 12) << "marker " << i;
  EXPECT_LT(turnBetween(dT, T), 0.0005);
  EXPECT_LT((dT.translation() - T.translation()).norm(), 0.001);
}
