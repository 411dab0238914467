// The sensor frame S derived from rest markers (docs/reference.md), checked
// against a grid placed with a known pose in the camera frame.
#include <gtest/gtest.h>

#include "core/rotation.hpp"
#include "core/sensor_frame.hpp"

using namespace onetip;

TEST(SensorFrame, RecoversAKnownGridPose) {
  const int rows = 7, cols = 9;
  const double sq = 1.5;
  Eigen::Isometry3d L_from_S = rigidFromTranslationYawPitchRoll({2, -1, 30}, 0.2, 0.3, -0.1);
  MarkerField rest(rows, cols);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      rest.set(r * cols + c, L_from_S * Eigen::Vector3d((c - 4) * sq, (r - 3) * sq, 0));
  const SensorFrame S = SensorFrame::fromRestMarkers(rest);
  // z must point away from the camera, so that L_from_S's z (pointing from the
  // camera into the scene for this pose) is recovered exactly
  EXPECT_TRUE(S.sensorFromLeft().isApprox(L_from_S.inverse(), 1e-9));
  const MarkerField inS = S.toSensor(rest);
  EXPECT_NEAR(inS.position[0].x(), -4 * sq, 1e-9);
  EXPECT_NEAR(inS.position[0].y(), -3 * sq, 1e-9);
}

TEST(SensorFrame, RejectsTooFewMarkers) {
  MarkerField rest(3, 3);
  rest.set(0, {0, 0, 10});
  rest.set(1, {1, 0, 10});
  EXPECT_THROW(SensorFrame::fromRestMarkers(rest), std::runtime_error);
}
