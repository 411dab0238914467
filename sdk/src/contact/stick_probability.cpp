#include "contact/stick_probability.hpp"

#include <cmath>
#include <numbers>

namespace onetip::contact {

double stickProbability(double drift_mm, double slip_threshold_mm, double reach_mm) {
  const double s = slip_threshold_mm * kStickScatterPerThreshold;
  // In logarithms: the Gaussian's density underflows long before the answer reaches 0.
  const double log_stick = -0.5 * (drift_mm * drift_mm) / (s * s) - 1.5 * std::log(2 * std::numbers::pi * s * s);
  const double log_slip = std::log(3.0 / (4.0 * std::numbers::pi * reach_mm * reach_mm * reach_mm));
  return 1.0 / (1.0 + std::exp(log_slip - log_stick));
}

}  // namespace onetip::contact
