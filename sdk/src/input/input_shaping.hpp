// input/input_shaping.hpp — per-axis dead zone and gain of the 6-D signal.
//
// For axis k (dx, dy, dz in mm; yaw, pitch, roll in degrees):
//   y_k = gain_k * sign(x_k) * max(0, |x_k| - dead_zone_k)
// The dead zone is a response threshold (the paper recommends one against the
// coupling it saw between x translation and rotation about y); subtracting it
// keeps the output continuous at the threshold.
#pragma once

#include <array>

#include "onetip/types.hpp"

namespace onetip::input {

struct InputShaping {
  std::array<double, 6> gain{1, 1, 1, 1, 1, 1};
  std::array<double, 6> dead_zone{0, 0, 0, 0, 0, 0};
  void validate() const;  // throws InputError naming the bad axis
  Input6 apply(const Input6& x) const;
};

}  // namespace onetip::input
