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
  EXPECT_NEAR(pose::rotationSpread(a), 0.6, 1e-12);  // a 2 x 2 square of side 1.2
  EXPECT_NEAR(pose::rotationSpread({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}), 0, 1e-12);
}
