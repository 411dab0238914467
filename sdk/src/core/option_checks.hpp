// core/option_checks.hpp — the one validation vocabulary for option structs
// (in the spirit of Ceres' Solver::Options checks). Each check throws an
// InputError in one message style:
//   "<field>: must be in [<lo>, <hi>] <unit>, got <value>"
//   "<field>: must be at least <lo> <unit>, got <value>"   (and finite)
//   "<field>: must be above <lo> <unit>, got <value>"      (and finite)
//   "<field>: must be finite, got <value>"
//   "<field>: must be a whole number, got <value>"
//   "<field>: must be below <other> (<other value>), got <value>"   (and finite)
// where <field> names the struct and the field ("options.queue_capacity",
// "image effects: noise_sigma"); the unit is omitted when empty. Ranges are
// closed; NaN and infinities are outside every range. Numbers print as %g
// does ("0.05", "600000", "1e+06", "nan") with more digits only when needed
// to read back the same double.
//
// Header-only, so modules that link no other part of core (os_outputs) can use it.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "core/error.hpp"

namespace onetip {

// The shortest %g-style text that reads back as `value`.
inline std::string numberText(double value) {
  char text[32];
  for (int digits = 6; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    if (!std::isfinite(value) || std::strtod(text, nullptr) == value) break;
  }
  return text;
}

// "[lo, hi] unit" as the messages print it.
inline std::string rangeText(double lo, double hi, std::string_view unit = {}) {
  std::string text = "[" + numberText(lo) + ", " + numberText(hi) + "]";
  if (!unit.empty()) text.append(" ").append(unit);
  return text;
}

// lo <= value <= hi (so value is finite).
inline void requireInRange(std::string_view field, double value, double lo, double hi, std::string_view unit = {}) {
  if (value >= lo && value <= hi) return;
  throw InputError(std::string(field) + ": must be in " + rangeText(lo, hi, unit) + ", got " + numberText(value));
}

// lo <= value < infinity.
inline void requireAtLeast(std::string_view field, double value, double lo, std::string_view unit = {}) {
  if (value >= lo && std::isfinite(value)) return;
  std::string bound = numberText(lo);
  if (!unit.empty()) bound.append(" ").append(unit);
  throw InputError(std::string(field) + ": must be at least " + bound + ", got " + numberText(value));
}

// lo < value < infinity.
inline void requireAbove(std::string_view field, double value, double lo, std::string_view unit = {}) {
  if (value > lo && std::isfinite(value)) return;
  std::string bound = numberText(lo);
  if (!unit.empty()) bound.append(" ").append(unit);
  throw InputError(std::string(field) + ": must be above " + bound + ", got " + numberText(value));
}

// Not NaN and not infinite.
inline void requireFinite(std::string_view field, double value) {
  if (std::isfinite(value)) return;
  throw InputError(std::string(field) + ": must be finite, got " + numberText(value));
}

// A whole number (ints, flags and enums carried as doubles).
inline void requireWhole(std::string_view field, double value) {
  if (std::isfinite(value) && std::trunc(value) == value) return;
  throw InputError(std::string(field) + ": must be a whole number, got " + numberText(value));
}

// value < other_value, value finite; `other` names the other field.
inline void requireBelow(std::string_view field, double value, std::string_view other, double other_value) {
  if (value < other_value && std::isfinite(value)) return;
  throw InputError(std::string(field) + ": must be below " + std::string(other) + " (" + numberText(other_value) +
                   "), got " + numberText(value));
}

}  // namespace onetip
