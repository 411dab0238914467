#include "haptics/servo_response.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "haptics/platform_kinematics.hpp"

namespace onetip::haptics {

namespace {
constexpr double kTickS = 1e-3;
}

void ServoResponseOptions::validate() const {
  if (!(control_rate_hz > 0.0 && control_rate_hz <= 1000.0))
    throw InputError("ServoResponseOptions.control_rate_hz: must be in (0, 1000] Hz");
  if (!(resolution_deg >= 0.0 && resolution_deg <= 10.0))
    throw InputError("ServoResponseOptions.resolution_deg: must be in [0, 10] deg");
  if (!(max_speed_deg_s > 0.0 && std::isfinite(max_speed_deg_s)))
    throw InputError("ServoResponseOptions.max_speed_deg_s: must be finite and positive");
}

ServoResponse::ServoResponse(const ServoResponseOptions& options) : options_(options) {
  options_.validate();
  angle_.fill(kServoMinDeg);
  target_ = angle_;
}

const std::array<double, 3>& ServoResponse::advance(const std::array<double, 3>& command, double dt_s) {
  if (!(dt_s > 0.0 && std::isfinite(dt_s))) throw InputError("ServoResponse::advance: dt_s must be finite and > 0");
  const double max_step = options_.max_speed_deg_s * kTickS;
  const double control_period = 1.0 / options_.control_rate_hz;
  for (double t = 0.0; t < dt_s - 0.5 * kTickS; t += kTickS) {
    if (time_to_control_s_ <= 0.5 * kTickS) {
      const std::array<double, 3> clamped = clampServoAngles(command);
      for (size_t i = 0; i < 3; ++i)
        target_[i] = options_.resolution_deg > 0.0
                         ? std::round(clamped[i] / options_.resolution_deg) * options_.resolution_deg
                         : clamped[i];
      time_to_control_s_ += control_period;
    }
    for (size_t i = 0; i < 3; ++i) {
      const double to_go = target_[i] - angle_[i];  // arrive exactly, not to within rounding
      angle_[i] = std::abs(to_go) <= max_step ? target_[i] : angle_[i] + std::copysign(max_step, to_go);
    }
    time_to_control_s_ -= kTickS;
  }
  return angle_;
}

}  // namespace onetip::haptics
