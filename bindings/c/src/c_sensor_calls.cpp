#include "c_sensor_calls.hpp"

#include <cmath>

namespace onetip::c_api {
namespace {
// Beyond what a clock can add: no limit.
constexpr double kNoLimitS = 1e9;
}  // namespace

void refuseInsideCallback(const CSensor& s, const char* call) {
  if (CallbackScope::inside(&s))
    throw CError(ONETIP_ERROR_STATE, std::string(call) + ": called from inside the sensor's own callback");
}

double waitTimeout(double timeout_s, const char* call) {
  if (std::isnan(timeout_s)) throw Error(ErrorKind::input, std::string(call) + ": timeout_s is NaN");
  return timeout_s < 0 || timeout_s >= kNoLimitS ? -1.0 : timeout_s;
}

bool waitForEvent(Sensor& sensor, Event& e, double timeout) {
  if (timeout >= 0) return sensor.waitEvent(e, timeout);
  // No limit: hour-long slices until an event, the end or a stop.
  for (;;) {
    if (sensor.waitEvent(e, 3600.0)) return true;
    if (!sensor.running()) return sensor.pollEvent(e);
  }
}

void requireArgument(const void* p, const char* call, const char* what) {
  requireNonNull(p, (std::string(call) + ": " + what).c_str());
}

}  // namespace onetip::c_api
