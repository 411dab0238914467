#include "devices/servo_calibration.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "haptics/platform_kinematics.hpp"

namespace onetip::devices {

void ServoCalibration::validate(const std::string& where) const {
  if (!std::isfinite(pulse_at_0deg_us)) throw InputError(where + ".pulse_at_0deg_us: must be finite");
  if (!(std::isfinite(us_per_deg) && std::abs(us_per_deg) >= 1.0 && std::abs(us_per_deg) <= 50.0))
    throw InputError(where + ".us_per_deg: magnitude must be in [1, 50]");
  if (!(min_pulse_us > 0.0 && max_pulse_us > min_pulse_us && max_pulse_us < 4000.0))
    throw InputError(where + ".min_pulse_us/max_pulse_us: need 0 < min < max < 4000");
  for (double deg : {haptics::kServoMinDeg, haptics::kServoMaxDeg}) {
    const double p = pulseUs(deg);
    if (p < min_pulse_us || p > max_pulse_us)
      throw InputError(where + ": " + std::to_string(deg) + " deg maps to " + std::to_string(p) +
                       " us, outside the servo's pulse range");
  }
}

int ServoCalibration::quarterMicroseconds(double degrees) const {
  return static_cast<int>(std::lround(4.0 * pulseUs(degrees)));
}

double ServoCalibration::degreesFromQuarterMicroseconds(int quarter_us) const {
  return (quarter_us / 4.0 - pulse_at_0deg_us) / us_per_deg;
}

}  // namespace onetip::devices
