#include <gtest/gtest.h>

#include <random>

#include "core/rotation.hpp"
#include "pose/rigid_fit.hpp"

using namespace onetip;
using pose::fitRigidMotion;

namespace {

std::vector<Eigen::Vector3d> cloud(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-3, 3);
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < n; ++i) p.emplace_back(u(rng), u(rng), 0.3 * u(rng));
  return p;
}

double angleBetween(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(a.transpose() * b).angle();
}

}  // namespace

TEST(RigidFit, RecoversExactMotions) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> ang(-0.6, 0.6), tr(-2, 2);
  for (int trial = 0; trial < 50; ++trial) {
    const auto a = cloud(20, rng);
    const Eigen::Isometry3d T =
        rigidFromTranslationYawPitchRoll({tr(rng), tr(rng), tr(rng)}, ang(rng), ang(rng), ang(rng));
    std::vector<Eigen::Vector3d> b;
    for (const auto& p : a) b.push_back(T * p);
    const auto fit = fitRigidMotion(a, b);
    ASSERT_TRUE(fit.ok);
    EXPECT_LT(angleBetween(fit.motion.linear(), T.linear()), 1e-9);
    EXPECT_LT((fit.motion.translation() - T.translation()).norm(), 1e-9);
    EXPECT_LT(fit.rms_mm, 1e-9);
    EXPECT_NEAR(fit.motion.linear().determinant(), 1.0, 1e-12);
  }
}

TEST(RigidFit, NeverReturnsAReflection) {
  // Planar points mirrored through their plane: the best proper rotation is
  // the identity (a reflection would fit exactly but is not a motion).
  std::vector<Eigen::Vector3d> a{{0, 0, 0.1}, {1, 0, 0.1}, {0, 1, 0.1}, {1, 1, 0.1}};
  std::vector<Eigen::Vector3d> b{{0, 0, -0.1}, {1, 0, -0.1}, {0, 1, -0.1}, {1, 1, -0.1}};
  const auto fit = fitRigidMotion(a, b);
  ASSERT_TRUE(fit.ok);
  EXPECT_NEAR(fit.motion.linear().determinant(), 1.0, 1e-12);
  EXPECT_NEAR((fit.motion.translation() - Eigen::Vector3d(0, 0, -0.2)).norm(), 0, 1e-9);
}

TEST(RigidFit, DegenerateSetsAreRefused) {
  EXPECT_FALSE(fitRigidMotion({{0, 0, 0}, {1, 0, 0}}, {{0, 0, 0}, {1, 0, 0}}).ok);
  // collinear
  EXPECT_FALSE(fitRigidMotion({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{0, 0, 1}, {1, 0, 1}, {2, 0, 1}}).ok);
}

TEST(RigidFit, RobustFitIgnoresAFewMarkersThatDoNotFollow) {
  std::mt19937 rng(5);
  const auto a = cloud(30, rng);
  const Eigen::Isometry3d T = rigidFromTranslationYawPitchRoll({0.3, -0.2, -0.5}, 0.05, 0.02, -0.03);
  std::vector<Eigen::Vector3d> b;
  for (const auto& p : a) b.push_back(T * p);
  for (int i = 0; i < 4; ++i) b[static_cast<size_t>(i)] += Eigen::Vector3d(0.3, 0, 0);  // slipping
  const auto plain = fitRigidMotion(a, b);
  const auto robust = pose::fitRigidMotionRobust(a, b, 0.03, 4);
  ASSERT_TRUE(robust.ok);
  EXPECT_LT((robust.motion.translation() - T.translation()).norm(),
            0.25 * (plain.motion.translation() - T.translation()).norm());
}

TEST(RigidFit, TranslationOnlyAndSpread) {
  const std::vector<Eigen::Vector3d> a{{0, 0, 0}, {1.2, 0, 0}, {0, 1.2, 0}, {1.2, 1.2, 0}};
  std::vector<Eigen::Vector3d> b;
  for (const auto& p : a) b.push_back(p + Eigen::Vector3d(0.1, 0.2, -0.3));
  const auto fit = pose::fitTranslation(a, b);
  ASSERT_TRUE(fit.ok);
  EXPECT_NEAR((fit.motion.translation() - Eigen::Vector3d(0.1, 0.2, -0.3)).norm(), 0, 1e-12);
  const Eigen::Vector2d square = pose::planarSpread(a);  // a 2 x 2 square of side 1.2
  EXPECT_NEAR(square.x(), 0.6, 1e-12);
  EXPECT_NEAR(square.y(), 0.6, 1e-12);
  const Eigen::Vector2d line = pose::planarSpread({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}});
  EXPECT_NEAR(line.x(), 0, 1e-12);
  EXPECT_NEAR(line.y(), std::sqrt(2.0 / 3.0), 1e-12);
}

TEST(RigidFit, RotationAboutZFromALineOfPoints) {
  // Three markers in a line (what sticks at the end of a twist): the general
  // fit is degenerate, the rotation about the pad normal is not.
  const std::vector<Eigen::Vector3d> a{{-1.2, 0.3, 0.1}, {0, 0.3, 0.1}, {1.2, 0.3, 0.1}};
  const Eigen::Isometry3d T = rigidFromTranslationYawPitchRoll({0.02, -0.01, 0.005}, 0.006, 0, 0);
  std::vector<Eigen::Vector3d> b;
  for (const auto& p : a) b.push_back(T * p);
  EXPECT_FALSE(fitRigidMotion(a, b).ok);
  const auto fit = pose::fitRotationAboutZ(a, b);
  ASSERT_TRUE(fit.ok);
  EXPECT_NEAR(angleBetween(fit.motion.linear(), T.linear()), 0, 1e-12);
  EXPECT_NEAR((fit.motion.translation() - T.translation()).norm(), 0, 1e-12);
}

namespace {

// A twisting contact (rotation by `yaw` about the origin) whose outer ring of
// four markers at 1.7 mm slips back by `lag` mm while the centre and the
// inner ring at 1.2 mm stick; relax = minus the circumferential direction
// (the skin was dragged along +yaw).
struct TwistCase {
  std::vector<Eigen::Vector3d> from, to, relax;
  std::vector<std::uint8_t> sticks;
};

TwistCase twistWithSlippingRing(double yaw, double lag) {
  TwistCase c;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  auto add = [&](double r, double phi, bool sticks) {
    const Eigen::Vector3d p(r * std::cos(phi), r * std::sin(phi), -0.4);
    const Eigen::Vector3d tangent(-std::sin(phi), std::cos(phi), 0);
    c.from.push_back(p);
    c.to.push_back(R * p - (sticks ? 0.0 : lag) * (R * tangent));
    c.relax.push_back(-tangent);
    c.sticks.push_back(sticks ? 1 : 0);
  };
  add(0, 0, true);
  for (int k = 0; k < 4; ++k) add(1.2, k * M_PI / 2, true);
  for (int k = 0; k < 4; ++k) add(1.7, M_PI / 4 + k * M_PI / 2, false);
  return c;
}

}  // namespace

TEST(RigidFit, TrimmedFitDropsTheLaggingRingNotTheStickingCore) {
  const double yaw = 0.33 * kRadPerDeg;
  const TwistCase c = twistWithSlippingRing(yaw, 0.03);
  const auto trimmed = pose::fitRigidMotionTrimmed(c.from, c.to, c.relax, 0.005, 0.01);
  ASSERT_TRUE(trimmed.fit.ok);
  EXPECT_EQ(trimmed.inlier, c.sticks);
  EXPECT_NEAR(Eigen::AngleAxisd(trimmed.fit.motion.linear()).angle(), yaw, 1e-9);
  // Without the direction the ring drags the fit until the sticking core shows
  // the largest residuals, and the core is what gets dropped.
  const auto blind = pose::fitRigidMotionTrimmed(c.from, c.to, {}, 0.005, 0.01);
  EXPECT_NE(blind.inlier, c.sticks);
  EXPECT_GT(std::abs(Eigen::AngleAxisd(blind.fit.motion.linear()).angle() - yaw), 0.05 * kRadPerDeg);
}

TEST(RigidFit, TrimmedFitRemovesASingleOutlierAndKeepsTheRest) {
  std::mt19937 rng(9);
  const auto a = cloud(20, rng);
  const Eigen::Isometry3d T = rigidFromTranslationYawPitchRoll({0.1, 0.05, -0.2}, 0.02, -0.01, 0.015);
  std::vector<Eigen::Vector3d> b, relax(a.size(), Eigen::Vector3d::UnitX());
  for (const auto& p : a) b.push_back(T * p);
  b[7] += Eigen::Vector3d(0, 0.05, 0);  // a mis-tracked marker, not lagging
  const auto trimmed = pose::fitRigidMotionTrimmed(a, b, relax, 0.005, 0.01);
  ASSERT_TRUE(trimmed.fit.ok);
  for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(trimmed.inlier[i], i == 7 ? 0 : 1) << i;
  EXPECT_NEAR(angleBetween(trimmed.fit.motion.linear(), T.linear()), 0, 1e-9);
}
