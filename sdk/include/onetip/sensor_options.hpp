/**
 * @file onetip/sensor_options.hpp
 * @brief How a Sensor runs: its threads and queues, and the processing settings
 * an application may tune (SensorOptions).
 *
 * Plain values with defaults. The fields, their types, defaults, ranges, units
 * and one-line docs come from one table, onetip/sensor_option_table.hpp, and so
 * does everything that checks or carries them: validate(), load()/save(),
 * table(), get()/set(), the C ABI (onetip_options) and the bindings.
 *
 * Axis arrays are in Input6 order [dx, dy, dz, yaw, pitch, roll]: mm for the
 * first three, degrees for the rest (docs/reference.md).
 *
 * File format (plain YAML or JSON; every key optional, a missing key keeps its
 * default, an unknown key is an error so typos do not pass silently; errors
 * name the file, line and key; `filter` is written by name):
 *
 *     queue_capacity: 2            lossless: false        playback_rate: 0
 *     working_range: [4, 4, 3, 15, 40, 40]   filter: one_euro   filter_beta: 0.05
 *
 * Thread rules: a SensorOptions is a plain value; concurrent reads are safe,
 * a write (set(), assignment) must not race with other uses of the same
 * object. The table is immutable static data.
 */
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "onetip/export.hpp"

namespace onetip {

/// The smoothing applied to the 6-D input before shaping (SensorOptions::filter).
enum class FilterKind : std::uint8_t {
  none = 0,            ///< No smoothing.
  moving_average = 1,  ///< The mean of the last SensorOptions::filter_window frames.
  one_euro = 2,        ///< The 1-euro filter (Casiez et al. 2012): little lag while moving, smooth at rest.
};

/// Six values in Input6 order [dx, dy, dz, yaw, pitch, roll].
using AxisArray = std::array<double, 6>;

/// The type of a table row, from its C++ type.
enum class OptionType : std::uint8_t {
  integer = 0,  ///< An int.
  real = 1,     ///< A double.
  flag = 2,     ///< A bool (0 or 1).
  choice = 3,   ///< An enum (FilterKind): a value in 0 .. number of OptionInfo::choices - 1.
  axes = 4,     ///< An AxisArray: six reals.
};

/**
 * @brief One row of the option table, as every surface sees it.
 *
 * Values travel as doubles (exact for every int, bool and enum here). The
 * strings are static: valid for as long as the library is loaded; never free them.
 */
struct OptionInfo {
  const char* name;        ///< The field, the options file's key, the Python attribute and the C key.
  OptionType type;         ///< How the value is carried.
  int count;               ///< Number of values: 1, or 6 for OptionType::axes.
  double min, max;
  /// @var min
  /// @brief Lower end of the closed range of every value, in the option's unit.
  /// @var max
  /// @brief Upper end of the closed range of every value, in the option's unit.
  const char* unit;        ///< "" when none; "mm|deg": mm for dx, dy, dz, degrees for yaw, pitch, roll.
  const char* doc;         ///< One line for generated help and bindings.
  AxisArray default_value; ///< The default; the first `count` entries are used.
  std::span<const char* const> choices;  ///< OptionType::choice: the names in value order ("none", ...); else empty.
};

/**
 * @brief The options of a Sensor; the defaults suit a live camera.
 *
 * Every field is one row of onetip/sensor_option_table.hpp; its key in the
 * options file, in get()/set() and in the C struct onetip_options is the
 * field's name. Assigning a field directly is not checked: validate(), the
 * Sensor constructor and save() check the whole struct. A plain value: the
 * const members may run concurrently; set() and assignment must not race with
 * other uses of the same object. load() and table() may be called from any thread.
 */
struct ONETIP_EXPORT SensorOptions {
#define ONETIP_OPTION(name, Type, min, max, unit, doc, ...) Type name{__VA_ARGS__};
#include "onetip/sensor_option_table.hpp"
#undef ONETIP_OPTION

  /// @return true when every field is equal (exact comparison of the doubles).
  bool operator==(const SensorOptions&) const = default;

  /**
   * @brief Checks every value against its range and the relations between
   * options (release_mm < press_mm).
   * @throws onetip::Error of kind ErrorKind::input naming the first bad field,
   *         its range and unit ("options.queue_capacity: must be in [1, 64] frames,
   *         got 0"); NaN and infinities are outside every range.
   */
  void validate() const;
  /**
   * @brief Reads an options file written by save() or by hand (format above),
   * over the defaults.
   * @param path a YAML or JSON file.
   * @return the options, valid.
   * @throws onetip::Error of kind ErrorKind::input naming the file, line and key
   *         when the file cannot be read, is not YAML or JSON, has an unknown
   *         key, or a value of the wrong type or out of its range.
   */
  static SensorOptions load(const std::string& path);
  /**
   * @brief Writes every field as YAML; the file is replaced atomically (never
   * half-written: a temporary file beside it is moved into place).
   * @param path the file to write; an existing regular file is replaced.
   * @throws onetip::Error of kind ErrorKind::input when the options are not
   *         valid (as validate()), or the file cannot be written (naming the
   *         path and the reason); the file is then left as it was.
   */
  void save(const std::string& path) const;

  /**
   * @brief The option table, one row per field in declaration order (the
   * order of the options file). Never throws; any thread.
   * @return a view of static rows, valid for as long as the library is loaded.
   */
  static std::span<const OptionInfo> table();
  /**
   * @brief Keyed read: value `index` of the option `name`.
   * @param name an OptionInfo::name, e.g. "press_mm".
   * @param index 0, or 0..5 (dx, dy, dz, yaw, pitch, roll) for axis arrays.
   * @return the value as a double in the option's unit (exact for integers,
   *         flags and choices).
   * @throws onetip::Error of kind ErrorKind::input for an unknown name or an
   *         index outside [0, count - 1].
   */
  double get(std::string_view name, int index = 0) const;
  /**
   * @brief Keyed write: sets value `index` of the option `name`.
   *
   * Checks the value against the option's range (and that integers, flags and
   * choices are whole numbers); it does not check relations between options
   * (release_mm < press_mm): validate() does.
   * @param name an OptionInfo::name, e.g. "press_mm".
   * @param value the new value in the option's unit (mm, degrees, Hz, ...).
   * @param index 0, or 0..5 (dx, dy, dz, yaw, pitch, roll) for axis arrays.
   * @throws onetip::Error of kind ErrorKind::input for an unknown name, a bad
   *         index, or a value out of range or not whole; the options are then
   *         unchanged.
   */
  void set(std::string_view name, double value, int index = 0);
};

}  // namespace onetip
