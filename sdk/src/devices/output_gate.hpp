// devices/output_gate.hpp — keeps a driver's outputs inside its SafeLimits.
//
// For each output i, with the previous output p_i and step s_i = maxStep(i):
//   next_i = clamp(clamp(want_i, min_i, max_i), p_i - s_i, p_i + s_i)
// Non-finite wants are not passed (the caller refuses the goal). retract()
// jumps to the rest outputs. The gate starts at rest.
#pragma once

#include <span>
#include <vector>

#include "devices/cutaneous_device.hpp"

namespace onetip::devices {

bool allFinite(std::span<const double> values);

class OutputGate {
 public:
  explicit OutputGate(const SafeLimits& limits);
  // Limits `want` (finite, one per output) and returns the outputs to send.
  const std::vector<double>& step(std::span<const double> want);
  const std::vector<double>& retract();
  const std::vector<double>& outputs() const noexcept { return outputs_; }

 private:
  SafeLimits limits_;
  std::vector<double> outputs_;
};

}  // namespace onetip::devices
