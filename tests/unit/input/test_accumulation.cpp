#include <gtest/gtest.h>

#include <cmath>

#include "core/rotation.hpp"
#include "input/pose_accumulator.hpp"

using namespace onetip;
using input::PoseAccumulator;

namespace {

// A finger motion since onset at time s in [0, 1]: combined yaw, pitch, roll
// about a pivot 6 mm above the contact, plus a slide.
Eigen::Isometry3d fingerAt(double s, bool single_axis) {
  const Eigen::Vector3d pivot(0, 0, 6);
  const double yaw = s * 12 * kRadPerDeg, pitch = single_axis ? 0 : s * 30 * kRadPerDeg,
               roll = single_axis ? 0 : -s * 25 * kRadPerDeg;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = rotationFromYawPitchRoll(yaw, pitch, roll);
  T.translation() = pivot - T.linear() * pivot + Eigen::Vector3d(single_axis ? 0 : 0.8 * s, 0, 0);
  return T;
}

double worstError(const Input6& a, const Input6& b) {
  double w = 0;
  const auto x = a.asArray(), y = b.asArray();
  for (size_t k = 0; k < 6; ++k) w = std::max(w, std::abs(x[k] - y[k]));
  return w;
}

}  // namespace

TEST(Accumulation, CompositionIsExactAndTheEulerSumIsNotForCombinedMotion) {
  const Eigen::Vector3d c0(0.3, -0.2, 0);
  PoseAccumulator acc;
  acc.reset(c0, 0);
  Eigen::Isometry3d previous = Eigen::Isometry3d::Identity();
  const int steps = 60;
  for (int k = 1; k <= steps; ++k) {
    const Eigen::Isometry3d now = fingerAt(double(k) / steps, false);
    acc.add(now * previous.inverse());
    previous = now;
  }
  const Input6 truth = input6FromMotion(fingerAt(1, false), c0);
  EXPECT_LT(worstError(acc.composed(), truth), 1e-9);
  const double gap = worstError(acc.eulerSum(), truth);
  std::printf("Euler-sum error after 12/30/-25 deg: %.3f\n", gap);
  EXPECT_GT(gap, 0.5);  // degrees or mm: the paper's accumulation drifts on combined motion
}

TEST(Accumulation, BothAgreeForRotationAboutOneAxisThroughTheContact) {
  const Eigen::Vector3d c0(0, 0, 0);
  PoseAccumulator acc;
  acc.reset(c0, 0);
  Eigen::Isometry3d previous = Eigen::Isometry3d::Identity();
  for (int k = 1; k <= 40; ++k) {
    const Eigen::Isometry3d now = fingerAt(k / 40.0, true);  // yaw about the vertical through c0
    acc.add(now * previous.inverse());
    previous = now;
  }
  EXPECT_LT(worstError(acc.composed(), acc.eulerSum()), 1e-9);
  EXPECT_NEAR(acc.composed().yaw, 12, 1e-9);
}

// The markers lie d below the contact surface and move with the surface point
// above them: a marker m = s - d n goes to F(s) - d n when the finger F carries
// the surface. Fed that marker-layer motion, the accumulator must report the
// finger's own F(c0) - c0; read at c0 itself it reports d sin(theta) of slide.
TEST(Accumulation, ReportsTheFingerNotTheMarkerLayerUnderTheEpidermis) {
  const Eigen::Vector3d c0(0.4, -0.3, 0), n = Eigen::Vector3d::UnitZ();
  const double d = 0.45;
  PoseAccumulator with_depth, at_markers;
  with_depth.reset(c0, d);
  at_markers.reset(c0, 0);
  Eigen::Isometry3d previous = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d finger = Eigen::Isometry3d::Identity();
  for (int k = 1; k <= 30; ++k) {
    finger = fingerAt(k / 30.0, false);
    // Marker layer: m -> F(m + d n) - d n, built point-wise from three markers.
    const auto layer = [&](const Eigen::Isometry3d& f, const Eigen::Vector3d& m) -> Eigen::Vector3d {
      return f * (m + d * n) - d * n;
    };
    Eigen::Isometry3d marker_motion = Eigen::Isometry3d::Identity();
    marker_motion.linear() = finger.linear();
    marker_motion.translation() = layer(finger, Eigen::Vector3d::Zero());
    ASSERT_LT((marker_motion * Eigen::Vector3d(1, 2, 0) - layer(finger, Eigen::Vector3d(1, 2, 0))).norm(), 1e-12);
    with_depth.add(marker_motion * previous.inverse());
    at_markers.add(marker_motion * previous.inverse());
    previous = marker_motion;
  }
  const Input6 truth = input6FromMotion(finger, c0);
  EXPECT_LT(worstError(with_depth.composed(), truth), 1e-9);
  const double tilt = Eigen::AngleAxisd(finger.linear()).angle();
  EXPECT_GT(worstError(at_markers.composed(), truth), 0.5 * d * std::sin(tilt));
}
