// The display device's kinematics against its stated geometry, and the
// BioTac-like sensor's basic physics (no contact, monotonic press, symmetry).
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "core/rotation.hpp"
#include "haptics/biotac_like_sensor.hpp"
#include "haptics/platform_kinematics.hpp"

using namespace onetip;
using namespace onetip::haptics;

TEST(PlatformKinematics, RestAndPurePressFollowThePulleyRadius) {
  const PlatformKinematics k;
  const auto rest = k.forward({30, 30, 30});
  EXPECT_NEAR(rest.z_mm, -1.5, 1e-12);
  EXPECT_NEAR(rest.roll_deg, 0.0, 1e-12);
  EXPECT_NEAR(rest.pitch_deg, 0.0, 1e-12);
  const auto pressed = k.forward({120, 120, 120});
  EXPECT_NEAR(pressed.z_mm, -1.5 + 1.5 * 90.0 * kRadPerDeg, 1e-12);
  EXPECT_NEAR(pressed.plane.normal.z(), 1.0, 1e-12);
  // Clamped to the servo range.
  EXPECT_NEAR(k.forward({250, 250, 250}).z_mm, k.forward({195, 195, 195}).z_mm, 1e-12);
  EXPECT_NEAR(k.forward({0, 0, 0}).z_mm, rest.z_mm, 1e-12);
}

TEST(PlatformKinematics, PlaneContainsTheVerticesAndTiltSignsAreAsDocumented) {
  const PlatformKinematics k;
  for (const std::array<double, 3> m : {std::array<double, 3>{150, 60, 60}, {40, 190, 100}, {77, 131, 180}}) {
    const auto pose = k.forward(m);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(pose.plane.normal.dot(k.vertex(i, m) - pose.plane.point), 0.0, 1e-9);
    const Eigen::Vector3d n = Eigen::AngleAxisd(pose.roll_deg * kRadPerDeg, Eigen::Vector3d::UnitY()) *
                              Eigen::AngleAxisd(pose.pitch_deg * kRadPerDeg, Eigen::Vector3d::UnitX()) *
                              Eigen::Vector3d::UnitZ();
    EXPECT_NEAR((n - pose.plane.normal).norm(), 0.0, 1e-12);
  }
  EXPECT_GT(k.forward({150, 60, 60}).pitch_deg, 5.0);  // front motor lifts the front
  EXPECT_GT(k.forward({60, 60, 150}).roll_deg, 5.0);   // motor 3 (rear left) lifts the left
  EXPECT_LT(k.forward({60, 150, 60}).roll_deg, -5.0);  // motor 2 (rear right) lifts the right
  EXPECT_THROW(PlatformKinematics(PlatformGeometry{-1.0, 7.0, 1.5}), InputError);
}

TEST(BiotacLikeSensor, RestsAtBaselineAndPressesMonotonically) {
  const BiotacLikeSensor sensor;
  const PlatformKinematics k;
  const auto rest = sensor.sense(k.forward({30, 30, 30}).plane);
  ASSERT_EQ(rest.size(), 20u);
  // At rest every fluid layer is h0 thick (Z = Z0): the divider reads 4095 / (2 + 0.05 (j mod 5)).
  for (int e = 0; e < 19; ++e) EXPECT_EQ(rest[static_cast<size_t>(e)], std::round(4095.0 / (2.0 + 0.05 * (e % 5))));
  EXPECT_EQ(rest[19], 500.0);
  double previous_pressure = rest[19], previous_centre = rest[0];
  for (double a = 60; a <= 195; a += 15) {
    const auto s = sensor.sense(k.forward({a, a, a}).plane);
    EXPECT_GE(s[19], previous_pressure);
    EXPECT_GE(s[0], previous_centre);
    previous_pressure = s[19];
    previous_centre = s[0];
    for (double v : s) EXPECT_TRUE(v >= 0 && v <= 4095);
  }
  EXPECT_GT(previous_pressure, 1000.0);
  // Tilting to lift the left side presses the left electrodes (x < 0) harder.
  const auto tilted = sensor.sense(k.forward({100, 100, 190}).plane);
  double left = 0, right = 0;
  for (int e = 0; e < 19; ++e) {
    const double delta = tilted[static_cast<size_t>(e)] - rest[static_cast<size_t>(e)];
    const double x = sensor.electrodes()[static_cast<size_t>(e)].x();
    if (x < -1) left += delta;
    if (x > 1) right += delta;
  }
  EXPECT_GT(left, right);
}

// The fluid layer's Z ~ 1 / h makes the response steepen with depth: the centre
// electrode gains more counts per mm of platform travel the deeper the press,
// until it nears the 12-bit ceiling. And the fluid pushed out from under the
// pad lifts the skin elsewhere, so the electrodes near the equator read below
// their rest values during a central press.
TEST(BiotacLikeSensor, FluidLayerSteepensWithDepthAndRedistributes) {
  const BiotacLikeSensor sensor;
  const PlatformKinematics k;
  auto centreAt = [&](double z_mm) {
    ContactPlane plate;
    plate.point = {0, 0, z_mm};
    return sensor.sense(plate)[0];
  };
  const double shallow_gain = centreAt(0.5) - centreAt(0.0);
  const double deep_gain = centreAt(1.5) - centreAt(1.0);
  EXPECT_GT(shallow_gain, 0.0);
  RecordProperty("centre_gain_counts_per_0_5mm", std::to_string(shallow_gain) + " then " + std::to_string(deep_gain));
  EXPECT_GT(deep_gain, 1.5 * shallow_gain);
  const auto rest = sensor.sense(k.forward({30, 30, 30}).plane);
  ContactPlane press;
  press.point = {0, 0, 1.0};
  const auto pressed = sensor.sense(press);
  for (int e = 7; e < 19; ++e) {  // the twelve at t = 68 deg, 3.4 mm above the plate
    EXPECT_LT(pressed[static_cast<size_t>(e)], rest[static_cast<size_t>(e)]) << "electrode " << e;
  }
}
