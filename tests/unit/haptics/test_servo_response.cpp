// The simulated servos against the paper's figures: top speed 60 deg in
// 0.07 s, new targets only at the 50 Hz control instants, 0.5 deg resolution,
// [30, 195] deg travel.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "haptics/servo_response.hpp"

using namespace onetip;
using namespace onetip::haptics;

namespace {
constexpr double kFullSpeedStep10Ms = 60.0 / 0.07 * 0.01;  // 8.57 deg per 10 ms
}

TEST(ServoResponse, MovesSixtyDegreesInSeventyMilliseconds) {
  ServoResponse servos;
  const std::array<double, 3> far{195, 195, 195};
  EXPECT_NEAR(servos.advance(far, 0.035)[0], 60.0, 1e-9);
  EXPECT_NEAR(servos.advance(far, 0.035)[1], 90.0, 1e-9);
  EXPECT_EQ(servos.advance(far, 1.0)[2], 195.0);  // and stops exactly at the target
}

TEST(ServoResponse, TakesANewTargetOnlyAtTheFiftyHertzControlInstants) {
  ServoResponse servos;
  EXPECT_NEAR(servos.advance({40, 40, 40}, 0.01)[0], 30.0 + kFullSpeedStep10Ms, 1e-9);
  // 10 ms later the next control instant is still 10 ms away: the servo keeps
  // going to 40 deg although the newest command is back at rest.
  EXPECT_NEAR(servos.advance({30, 30, 30}, 0.01)[0], 40.0, 1e-9);
  // At t = 20 ms the rest command is taken.
  EXPECT_NEAR(servos.advance({30, 30, 30}, 0.01)[0], 40.0 - kFullSpeedStep10Ms, 1e-9);
}

TEST(ServoResponse, RoundsToTheResolutionAndClampsToTheTravel) {
  ServoResponse servos;
  const auto& settled = servos.advance({100.3, 250.0, -5.0}, 1.0);
  EXPECT_DOUBLE_EQ(settled[0], 100.5);
  EXPECT_DOUBLE_EQ(settled[1], 195.0);
  EXPECT_DOUBLE_EQ(settled[2], 30.0);
  ServoResponseOptions exact;
  exact.resolution_deg = 0.0;
  ServoResponse unrounded(exact);
  EXPECT_EQ(unrounded.advance({100.3, 100.3, 100.3}, 1.0)[0], 100.3);
}

TEST(ServoResponse, RefusesBadOptionsAndIntervals) {
  ServoResponseOptions o;
  o.control_rate_hz = 0.0;
  EXPECT_THROW(ServoResponse{o}, InputError);
  o = {};
  o.max_speed_deg_s = -1.0;
  EXPECT_THROW(ServoResponse{o}, InputError);
  o = {};
  o.resolution_deg = -0.5;
  EXPECT_THROW(ServoResponse{o}, InputError);
  ServoResponse servos;
  EXPECT_THROW(servos.advance({30, 30, 30}, 0.0), InputError);
}
