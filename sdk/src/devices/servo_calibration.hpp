// devices/servo_calibration.hpp — per-servo angle-to-pulse calibration of the
// 3-servo cable platform (haptics/platform_kinematics.hpp: motor 1 front,
// motors 2 and 3 rear; angles in degrees, range [30, 195] deg).
//
//   pulse_us(theta) = pulse_at_0deg_us + us_per_deg * theta
// us_per_deg may be negative (a servo mounted mirrored). The Maestro takes
// quarter-microseconds: target = round(4 * pulse_us). Defaults: 600 us at
// 0 deg and 10 us/deg (900 us at 30 deg, 2550 us at 195 deg), inside the
// pulse range [500, 2600] us most hobby servos accept.
#pragma once

#include <array>
#include <string>

namespace onetip::devices {

struct ServoCalibration {
  double pulse_at_0deg_us = 600.0;
  double us_per_deg = 10.0;
  double min_pulse_us = 500.0;   // the servo's own accepted pulse range
  double max_pulse_us = 2600.0;

  // Throws InputError naming `where` when the map is degenerate or sends the
  // platform's safe angle range [30, 195] deg outside [min_pulse_us, max_pulse_us].
  void validate(const std::string& where) const;
  double pulseUs(double degrees) const { return pulse_at_0deg_us + us_per_deg * degrees; }
  int quarterMicroseconds(double degrees) const;
  double degreesFromQuarterMicroseconds(int quarter_us) const;
};

using PlatformServoCalibration = std::array<ServoCalibration, 3>;

}  // namespace onetip::devices
