#include "haptics/display_grid.hpp"

#include <cmath>
#include <cstdio>

#include "core/error.hpp"

namespace onetip::haptics {

std::vector<double> gridAngles(double step_deg) {
  if (!(step_deg > 0.0 && step_deg <= kServoMaxDeg - kServoMinDeg))
    throw InputError("step: " + std::to_string(step_deg) + " deg is not in (0, 165]");
  // Count first: a tiny step must be refused before it costs anything.
  const double per_motor = std::floor((kServoMaxDeg - kServoMinDeg - 1e-9) / step_deg) + 1.0;
  if (per_motor * per_motor * per_motor > static_cast<double>(kMaxGridConfigurations)) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "step: %g deg gives %.0f^3 = %.3g configurations, more than the %zu bound (%.0f MB of data at "
                  "20 channels); use a step of at least %.2f deg",
                  step_deg, per_motor, per_motor * per_motor * per_motor, kMaxGridConfigurations,
                  per_motor * per_motor * per_motor * 23 * 4 / 1e6, kMinGridStepDeg);
    throw InputError(text);
  }
  std::vector<double> angles;
  for (int i = 0;; ++i) {
    const double a = kServoMinDeg + i * step_deg;
    if (a >= kServoMaxDeg - 1e-9) break;
    angles.push_back(a);
  }
  return angles;
}

std::vector<std::array<double, 3>> gridConfigurations(double step_deg) {
  const auto a = gridAngles(step_deg);
  std::vector<std::array<double, 3>> out;
  out.reserve(a.size() * a.size() * a.size());
  for (double m1 : a)
    for (double m2 : a)
      for (double m3 : a) out.push_back({m1, m2, m3});
  return out;
}

TactileDataset simulateDataset(const PlatformKinematics& device, const TactileSensorModel& sensor, double step_deg) {
  TactileDataset d;
  d.channels = sensor.channels();
  std::vector<double> s(static_cast<size_t>(d.channels));
  for (const auto& m : gridConfigurations(step_deg)) {
    sensor.sense(device.forward(m).plane, s.data());
    d.append(m, s);
  }
  return d;
}

}  // namespace onetip::haptics
