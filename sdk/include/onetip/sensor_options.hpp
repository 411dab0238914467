// onetip/sensor_options.hpp — how a Sensor runs: its threads and queues, and
// the processing settings an application may tune. Plain values with
// defaults; the fields, their types, defaults, ranges, units and one-line docs
// come from ONE table, onetip/sensor_option_table.hpp (read it for each
// option's meaning), and so does everything that checks or carries them:
// validate(), load()/save(), table(), get()/set(), the C ABI and the bindings.
//
// Axis arrays are in Input6 order [dx, dy, dz, yaw, pitch, roll]: mm for the
// first three, degrees for the rest (docs/reference.md).
//
// File format (plain YAML or JSON; every key optional, a missing key keeps its
// default, an unknown key is an error so typos do not pass silently; errors
// name the file, line and key):
//   queue_capacity: 2            lossless: false        playback_rate: 0
//   working_range: [4, 4, 3, 15, 40, 40]   filter: one_euro   filter_beta: 0.05
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "onetip/export.hpp"

namespace onetip {

enum class FilterKind : std::uint8_t {
  none = 0,            // no smoothing
  moving_average = 1,  // the mean of the last filter_window frames (the paper's filter)
  one_euro = 2,        // the 1-euro filter (Casiez et al. 2012): little lag while moving
};

// Six values in Input6 order [dx, dy, dz, yaw, pitch, roll].
using AxisArray = std::array<double, 6>;

// The type of a table row, from its C++ type.
enum class OptionType : std::uint8_t {
  integer = 0,  // int
  real = 1,     // double
  flag = 2,     // bool (0 or 1)
  choice = 3,   // an enum (FilterKind): a value in 0..count of `choices` - 1
  axes = 4,     // AxisArray: six reals
};

// One row of the table, as every surface sees it. Values travel as doubles
// (exact for every int, bool and enum here).
struct OptionInfo {
  const char* name;        // field, file key, Python attribute, C key
  OptionType type;
  int count;               // values: 1, or 6 for axes
  double min, max;         // closed range of every value
  const char* unit;        // "" when none; "mm|deg": mm for dx..dz, degrees for yaw..roll
  const char* doc;         // one line
  AxisArray default_value; // the first `count` are used
  std::span<const char* const> choices;  // choice: the names in value order ("none", ...); else empty
};

struct ONETIP_EXPORT SensorOptions {
#define ONETIP_OPTION(name, Type, min, max, unit, doc, ...) Type name{__VA_ARGS__};
#include "onetip/sensor_option_table.hpp"
#undef ONETIP_OPTION

  bool operator==(const SensorOptions&) const = default;

  // Throws Error(ErrorKind::input) naming the first bad field, its range and
  // unit ("options.queue_capacity: must be in [1, 64] frames, got 0").
  void validate() const;
  // Reads a file written by save() or by hand (format above); throws
  // Error(ErrorKind::input) naming the file, line and key when it cannot.
  static SensorOptions load(const std::string& path);
  // Writes every field; the file is replaced atomically (never half-written).
  void save(const std::string& path) const;

  // The table, one row per field in declaration order.
  static std::span<const OptionInfo> table();
  // Keyed access: value `index` (0, or 0..5 for axes) of the option `name`.
  // set() checks the range (and that integers, flags and choices are whole
  // numbers) and leaves the options unchanged when it throws
  // Error(ErrorKind::input); so does an unknown name or index.
  double get(std::string_view name, int index = 0) const;
  void set(std::string_view name, double value, int index = 0);
};

}  // namespace onetip
