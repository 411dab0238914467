// The pose's reported uncertainty (pose/pose_uncertainty.hpp) on synthetic
// stick sets whose information is known in closed form, and the motion prior
// in the directions a set does not fix.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/rotation.hpp"
#include "pose/pose_uncertainty.hpp"

using namespace onetip;
using namespace onetip::pose;

namespace {

// A square grid of n x n points, pitch 1 mm, centred on `centre` in the plane z = centre.z.
std::vector<Eigen::Vector3d> grid(int n, const Eigen::Vector3d& centre) {
  std::vector<Eigen::Vector3d> p;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) p.push_back(centre + Eigen::Vector3d(c - (n - 1) / 2.0, r - (n - 1) / 2.0, 0));
  return p;
}

PoseUncertaintyOptions priorOnly(double turn_deg, double slide_mm) {
  PoseUncertaintyOptions o;
  o.relative_increment_error = 0;
  o.unseen_turn_deg_per_sqrt_s = turn_deg;
  o.unseen_slide_mm_per_sqrt_s = slide_mm;
  return o;
}

}  // namespace

TEST(PoseUncertainty, ASymmetricGridFixesEverythingWithTheLeastSquaresVariance) {
  const Eigen::Vector3d c(0.3, -0.2, 1.0);
  const std::vector<Eigen::Vector3d> pts = grid(5, c);
  const double sigma = 0.002;
  const StickInformation info = stickInformation(pts, std::vector<double>(pts.size(), 1.0), c, sigma, 0.01);
  EXPECT_EQ(info.fixed_directions, 6);
  // The set counts as one marker at its spread (a shared error does not average out). About the
  // centroid the translation decouples from the turn: var = sigma^2 per axis.
  for (int k = 3; k < 6; ++k) EXPECT_NEAR(info.fixed_covariance(k, k), sigma * sigma, 1e-15);
  // The turn about S.z: var = sigma^2 / mean(x^2 + y^2); the grid's sum is 2 * 5 * (4 + 1 + 0 + 1 + 4) = 100.
  EXPECT_NEAR(info.fixed_covariance(2, 2), sigma * sigma / (100.0 / 25.0), 1e-15);
  // Weights that are all equal do not change that; unequal ones move the centroid and the spread.
  const StickInformation half = stickInformation(pts, std::vector<double>(pts.size(), 0.5), c, sigma, 0.01);
  EXPECT_NEAR(half.fixed_covariance(3, 3), info.fixed_covariance(3, 3), 1e-15);
}

TEST(PoseUncertainty, WeightsThatSitOnOneMarkerFixNoTurnAndTheTurnTakesThePrior) {
  // Two markers 2 mm apart, the second's weight 1e-200: the set's radius of gyration is 1e-100 mm, far
  // within the noise. It is a point: its turns are unfixed, and after one frame each turn's sd is the
  // prior's, 10 deg/sqrt(s) over 1/30 s (1.83 deg), not sigma / g.
  const std::vector<Eigen::Vector3d> pts = {{0, 0, 0}, {2, 0, 0}};
  const StickInformation info = stickInformation(pts, {1.0, 1e-200}, Eigen::Vector3d::Zero(), 0.001, 0.01);
  EXPECT_EQ(info.fixed_directions, 3);  // a point fixes its own displacement only
  PoseUncertainty u(priorOnly(10, 0));
  u.reset(Eigen::Vector3d::Zero());
  u.add(info, Eigen::Isometry3d::Identity(), 1.0 / 30);
  const Input6 sd = u.sd();
  for (double turn : {sd.yaw, sd.pitch, sd.roll}) EXPECT_NEAR(turn, 10 * std::sqrt(1.0 / 30), 1e-6);
}

TEST(PoseUncertainty, ALineDoesNotFixTheTurnAboutItselfAndThatTurnGrowsAsThePriorSays) {
  std::vector<Eigen::Vector3d> line;
  for (int i = -3; i <= 3; ++i) line.push_back({0.5 * i, 0, 0});
  const StickInformation info =
      stickInformation(line, std::vector<double>(line.size(), 1.0), Eigen::Vector3d::Zero(), 0.001, 0.01);
  EXPECT_EQ(info.fixed_directions, 5);
  PoseUncertainty u(priorOnly(10, 0));
  u.reset(Eigen::Vector3d::Zero());
  const double dt = 1.0 / 30;
  for (int k = 0; k < 90; ++k) u.add(info, Eigen::Isometry3d::Identity(), dt);
  // The turn about S.x (pitch) is a random walk: 10 deg/sqrt(s) over 3 s.
  EXPECT_NEAR(u.sd().pitch, 10 * std::sqrt(3.0), 1e-6);
  // The turns the line fixes keep the fit's own variance sigma^2 / mean(x^2), mean(x^2) = 7 / 7 mm^2.
  const double fixed_deg = 0.001 / std::sqrt(1.0) * 180 / std::numbers::pi;
  EXPECT_NEAR(u.sd().yaw, fixed_deg, 1e-9);
  EXPECT_NEAR(u.sd().roll, fixed_deg, 1e-9);
  EXPECT_NEAR(u.sd().dx, 0.001, 1e-12);
}

TEST(PoseUncertainty, WithoutStickingMarkersEveryDirectionTakesThePrior) {
  PoseUncertainty u(priorOnly(20, 0.5));
  u.reset(Eigen::Vector3d(0, 0, 1));
  for (int k = 0; k < 40; ++k) u.add(StickInformation{}, Eigen::Isometry3d::Identity(), 0.05);
  const Input6 sd = u.sd();
  for (double v : {sd.dx, sd.dy, sd.dz}) EXPECT_NEAR(v, 0.5 * std::sqrt(2.0), 1e-9);
  for (double v : {sd.yaw, sd.pitch, sd.roll}) EXPECT_NEAR(v, 20 * std::sqrt(2.0), 1e-9);
}

TEST(PoseUncertainty, TheModelErrorGrowsWithTheDistanceTravelledLikeAnOdometer) {
  PoseUncertaintyOptions o = priorOnly(0, 0);
  o.relative_increment_error = 0.1;
  PoseUncertainty u(o);
  u.reset(Eigen::Vector3d::Zero());
  const std::vector<Eigen::Vector3d> pts = grid(5, Eigen::Vector3d::Zero());
  Eigen::Isometry3d step = Eigen::Isometry3d::Identity();
  step.translation() = Eigen::Vector3d(0.02, 0, 0);
  for (int k = 0; k < 100; ++k) {
    const Eigen::Vector3d c(0.02 * (k + 1), 0, 0);  // the set moves with the finger
    std::vector<Eigen::Vector3d> moved;
    for (const auto& p : pts) moved.push_back(p + c);
    u.add(stickInformation(moved, std::vector<double>(moved.size(), 1.0), c, 1e-6, 0.01), step, 1.0 / 30);
  }
  // 100 steps of 0.02 mm, each with an sd of 10 % of its length: sqrt(100) * 0.002 mm.
  EXPECT_NEAR(u.sd().dx, 0.02, 1e-6);
  EXPECT_NEAR(u.sd().dy, 0.02, 1e-6);
  EXPECT_LT(u.sd().yaw, 1e-3);  // no turn, no turn error
}

TEST(PoseUncertainty, TheErrorTurnsWithTheFinger) {
  // A line along S.x leaves the turn about S.x unfixed: one second of the prior puts 10 deg of sd there.
  std::vector<Eigen::Vector3d> line;
  for (int i = -3; i <= 3; ++i) line.push_back({0.5 * i, 0, 0});
  const std::vector<double> ones(line.size(), 1.0);
  PoseUncertainty u(priorOnly(10, 0));
  u.reset(Eigen::Vector3d::Zero());
  u.add(stickInformation(line, ones, Eigen::Vector3d::Zero(), 1e-9, 0.01), Eigen::Isometry3d::Identity(), 1.0);
  ASSERT_NEAR(u.sd().pitch, 10, 1e-6);
  // Then a quarter turn about S.z, every direction fixed (a grid, no prior): the error about S.x is now
  // about S.y, the finger's long axis (roll).
  const std::vector<Eigen::Vector3d> pts = grid(5, Eigen::Vector3d::Zero());
  Eigen::Isometry3d turn = Eigen::Isometry3d::Identity();
  turn.linear() = Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  u.add(stickInformation(pts, std::vector<double>(pts.size(), 1.0), Eigen::Vector3d::Zero(), 1e-9, 0.01), turn,
        1.0);
  EXPECT_NEAR(u.sd().roll, 10, 1e-6);
  EXPECT_LT(u.sd().pitch, 1e-6);
}

TEST(PoseUncertainty, BadOptionsAreRefusedByName) {
  PoseUncertaintyOptions o;
  o.relative_increment_error = 2;
  EXPECT_THROW(
      {
        try {
          o.validate();
        } catch (const std::exception& e) {
          EXPECT_NE(std::string(e.what()).find("relative_increment_error"), std::string::npos);
          throw;
        }
      },
      std::exception);
}
