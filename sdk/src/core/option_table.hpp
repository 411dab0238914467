// core/option_table.hpp — the SensorOptions table (onetip/sensor_option_table.hpp)
// made usable: a constexpr row per option (name, type, range, unit, doc and the
// struct's own default) with typed accessors, and everything derived from it
// that needs no I/O: range checks, keyed get/set, the one validate().
//
// Values travel as doubles (exact for the ints, bools and enums of the table).
// Messages follow core/option_checks.hpp with the field named
// "options.<name>", or "options.<name>[k] (<axis>)" for axis arrays, and the
// unit of that value (mm for dx..dz, deg for yaw..roll when the unit is "mm|deg").
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include "onetip/sensor_options.hpp"

namespace onetip::option_table {

// The rows, in table order.
std::span<const OptionInfo> rows();
// The row of `name`; throws InputError "options: no option named '<name>'".
std::size_t indexOf(std::string_view name);

// "options.gain[2] (dz)" or "options.queue_capacity".
std::string fieldName(const OptionInfo& row, int index);
// The unit of value `index` ("mm" for dz of an "mm|deg" row).
std::string_view unitOf(const OptionInfo& row, int index);

// Value `index` of row `option`; throws InputError when index is outside 0..count-1.
double get(const SensorOptions& o, std::size_t option, int index);
// Checks value (range; whole numbers for integer, flag and choice) and sets it;
// on InputError `o` is unchanged.
void set(SensorOptions& o, std::size_t option, int index, double value);

// Every value in its row's range, then the relations between options
// (release_mm < press_mm); throws InputError naming the first bad field.
void validate(const SensorOptions& o);

}  // namespace onetip::option_table
