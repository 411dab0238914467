#include "devices/output_gate.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/error.hpp"

namespace onetip::devices {

void SafeLimits::validate() const {
  if (outputs.empty()) throw InputError("SafeLimits.outputs: empty");
  if (!(command_rate_hz > 0.0 && command_rate_hz <= 10000.0))
    throw InputError("SafeLimits.command_rate_hz: must be in (0, 10000]");
  if (!(watchdog_timeout_s > 0.0 && watchdog_timeout_s <= 10.0))
    throw InputError("SafeLimits.watchdog_timeout_s: must be in (0, 10]");
  for (const OutputLimit& o : outputs) {
    const std::string where = "SafeLimits.outputs[" + o.name + "]";
    if (!(std::isfinite(o.min) && std::isfinite(o.max) && o.min < o.max))
      throw InputError(where + ": needs finite min < max");
    if (!(o.rest >= o.min && o.rest <= o.max)) throw InputError(where + ".rest: outside [min, max]");
    if (!(o.max_rate > 0.0)) throw InputError(where + ".max_rate: must be positive");
  }
}

std::vector<double> SafeLimits::rest() const {
  std::vector<double> r;
  for (const OutputLimit& o : outputs) r.push_back(o.rest);
  return r;
}

bool allFinite(std::span<const double> values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

OutputGate::OutputGate(const SafeLimits& limits) : limits_(limits), outputs_(limits.rest()) { limits_.validate(); }

const std::vector<double>& OutputGate::step(std::span<const double> want) {
  assert(want.size() == outputs_.size() && allFinite(want));
  for (size_t i = 0; i < outputs_.size(); ++i) {
    const OutputLimit& o = limits_.outputs[i];
    const double s = limits_.maxStep(i);
    const double in_range = std::clamp(want[i], o.min, o.max);
    outputs_[i] = std::clamp(in_range, std::max(o.min, outputs_[i] - s), std::min(o.max, outputs_[i] + s));
  }
  return outputs_;
}

const std::vector<double>& OutputGate::retract() {
  outputs_ = limits_.rest();
  return outputs_;
}

}  // namespace onetip::devices
