#include "input/input_shaping.hpp"

#include <cmath>
#include <string>

#include "core/option_checks.hpp"

namespace onetip::input {

namespace {
constexpr std::array<const char*, 6> kAxis{"dx", "dy", "dz", "yaw", "pitch", "roll"};
}

void InputShaping::validate() const {
  for (size_t k = 0; k < 6; ++k) {
    requireFinite(std::string("input shaping: gain of ") + kAxis[k], gain[k]);
    requireAtLeast(std::string("input shaping: dead_zone of ") + kAxis[k], dead_zone[k], 0);
  }
}

Input6 InputShaping::apply(const Input6& x) const {
  auto v = x.asArray();
  for (size_t k = 0; k < 6; ++k) {
    const double magnitude = std::max(0.0, std::abs(v[k]) - dead_zone[k]);
    v[k] = gain[k] * std::copysign(magnitude, v[k]);
  }
  return Input6::fromArray(v);
}

}  // namespace onetip::input
