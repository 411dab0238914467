// Rotation and 6-D input conventions (docs/reference.md) against independent
// constructions: axis-angle products and hand-computed motions.
#include <gtest/gtest.h>

#include <random>

#include "core/rotation.hpp"

using namespace onetip;

TEST(Rotation, YawIsAboutZPitchAboutXRollAboutY) {
  const Eigen::Vector3d ex = Eigen::Vector3d::UnitX(), ey = Eigen::Vector3d::UnitY();
  // yaw +90 deg turns x into y (right-hand rule about z)
  EXPECT_TRUE((rotationFromYawPitchRoll(M_PI / 2, 0, 0) * ex).isApprox(ey, 1e-12));
  // pitch +90 deg about x turns y into z
  EXPECT_TRUE((rotationFromYawPitchRoll(0, M_PI / 2, 0) * ey).isApprox(Eigen::Vector3d::UnitZ(), 1e-12));
  // roll +90 deg about y turns z into x
  EXPECT_TRUE((rotationFromYawPitchRoll(0, 0, M_PI / 2) * Eigen::Vector3d::UnitZ()).isApprox(ex, 1e-12));
}

TEST(Rotation, RoundTripOverTheWorkingRange) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> yaw(-1.5, 1.5), tilt(-1.2, 1.2);
  for (int i = 0; i < 1000; ++i) {
    const double a = yaw(rng), b = tilt(rng), c = tilt(rng);
    const Eigen::Matrix3d R = Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
                              Eigen::AngleAxisd(c, Eigen::Vector3d::UnitY()).toRotationMatrix() *
                              Eigen::AngleAxisd(b, Eigen::Vector3d::UnitX()).toRotationMatrix();
    const Eigen::Vector3d ypr = yawPitchRollFromRotation(R);
    EXPECT_NEAR(ypr[0], a, 1e-9);
    EXPECT_NEAR(ypr[1], b, 1e-9);
    EXPECT_NEAR(ypr[2], c, 1e-9);
  }
}

TEST(Input6, PressTranslationAndCoupling) {
  const Eigen::Vector3d c0(1.0, -2.0, 0.0);
  // a press of 1.5 mm into the pad is a motion along -z
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(0.5, 0.25, -1.5);
  Input6 v = input6FromMotion(T, c0);
  EXPECT_NEAR(v.dx, 0.5, 1e-12);
  EXPECT_NEAR(v.dy, 0.25, 1e-12);
  EXPECT_NEAR(v.dz, 1.5, 1e-12);
  EXPECT_NEAR(v.yaw, 0, 1e-12);
  // a yaw of 10 deg about the S origin moves c0 sideways: the coupling is kept
  T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(10 * kRadPerDeg, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  v = input6FromMotion(T, c0);
  EXPECT_NEAR(v.yaw, 10, 1e-9);
  const Eigen::Vector3d moved = T * c0;
  EXPECT_NEAR(v.dx, moved.x() - c0.x(), 1e-12);
  EXPECT_NEAR(v.dy, moved.y() - c0.y(), 1e-12);
}

TEST(Input6, MotionFromInput6InvertsInput6FromMotion) {
  const Eigen::Vector3d c0(1.0, -2.0, 0.5);
  const Eigen::Isometry3d T = rigidFromTranslationYawPitchRoll(Eigen::Vector3d(0.3, -0.2, -1.1), 0.4, -0.3, 0.2);
  const Eigen::Isometry3d back = motionFromInput6(input6FromMotion(T, c0), c0);
  EXPECT_LT((back.matrix() - T.matrix()).cwiseAbs().maxCoeff(), 1e-12);
}
