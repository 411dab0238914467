#include "core/option_table.hpp"

#include <array>

#include "core/error.hpp"
#include "core/option_checks.hpp"

namespace onetip::option_table {
namespace {

constexpr std::array<const char*, 3> kFilterNames{"none", "moving_average", "one_euro"};
constexpr std::array<const char*, 6> kAxisNames{"dx", "dy", "dz", "yaw", "pitch", "roll"};

// How each C++ type of the table is described and carried as doubles.
template <typename T>
struct Traits;

template <typename T, OptionType kType>
struct Scalar {
  static constexpr OptionType type = kType;
  static constexpr int count = 1;
  static constexpr std::span<const char* const> choices{};
  static constexpr AxisArray values(T v) { return {static_cast<double>(v), 0, 0, 0, 0, 0}; }
  static double get(const T& v, int) { return static_cast<double>(v); }
  static void set(T& field, int, double x) { field = static_cast<T>(static_cast<long long>(x)); }
};
template <>
struct Traits<int> : Scalar<int, OptionType::integer> {};
template <>
struct Traits<bool> : Scalar<bool, OptionType::flag> {
  static void set(bool& field, int, double x) { field = x != 0; }
};
template <>
struct Traits<FilterKind> : Scalar<FilterKind, OptionType::choice> {
  static constexpr std::span<const char* const> choices{kFilterNames};
};
template <>
struct Traits<double> : Scalar<double, OptionType::real> {
  static void set(double& field, int, double x) { field = x; }
};
template <>
struct Traits<AxisArray> {
  static constexpr OptionType type = OptionType::axes;
  static constexpr int count = 6;
  static constexpr std::span<const char* const> choices{};
  static constexpr AxisArray values(const AxisArray& v) { return v; }
  static double get(const AxisArray& v, int k) { return v[static_cast<std::size_t>(k)]; }
  static void set(AxisArray& field, int k, double x) { field[static_cast<std::size_t>(k)] = x; }
};

struct Access {
  double (*get)(const SensorOptions&, int);
  void (*set)(SensorOptions&, int, double);
};
template <typename T, T SensorOptions::*kField>
double getField(const SensorOptions& o, int k) {
  return Traits<T>::get(o.*kField, k);
}
template <typename T, T SensorOptions::*kField>
void setField(SensorOptions& o, int k, double x) {
  Traits<T>::set(o.*kField, k, x);
}

constexpr SensorOptions kDefaults{};

constexpr std::array kRows{
#define ONETIP_OPTION(name, Type, lo, hi, unit, doc, ...) \
  OptionInfo{#name,                                       \
             Traits<Type>::type,                          \
             Traits<Type>::count,                         \
             lo,                                          \
             hi,                                          \
             unit,                                        \
             doc,                                         \
             Traits<Type>::values(kDefaults.name),        \
             Traits<Type>::choices},
#include "onetip/sensor_option_table.hpp"
#undef ONETIP_OPTION
};

constexpr std::array kAccess{
#define ONETIP_OPTION(name, Type, ...) \
  Access{&getField<Type, &SensorOptions::name>, &setField<Type, &SensorOptions::name>},
#include "onetip/sensor_option_table.hpp"
#undef ONETIP_OPTION
};

constexpr bool sameText(const char* a, const char* b) {
  while (*a && *a == *b) ++a, ++b;
  return *a == *b;
}

// The table is checked when it compiles: names unique, ranges ordered, every
// default inside its range, a choice's range spanning exactly its names.
constexpr bool wellFormed() {
  for (std::size_t i = 0; i < kRows.size(); ++i) {
    const OptionInfo& r = kRows[i];
    if (!(r.min <= r.max)) return false;
    for (int k = 0; k < r.count; ++k)
      if (!(r.default_value[static_cast<std::size_t>(k)] >= r.min &&
            r.default_value[static_cast<std::size_t>(k)] <= r.max))
        return false;
    if (r.type == OptionType::choice && (r.min != 0 || r.max != static_cast<double>(r.choices.size()) - 1))
      return false;
    if (r.type == OptionType::flag && (r.min != 0 || r.max != 1)) return false;
    for (std::size_t j = 0; j < i; ++j)
      if (sameText(kRows[j].name, r.name)) return false;
  }
  return true;
}
static_assert(wellFormed(), "onetip/sensor_option_table.hpp: a duplicate name, an empty range or a default outside it");
static_assert(kAccess.size() == kRows.size());

void requireIndex(const OptionInfo& row, int index) {
  if (index < 0 || index >= row.count)
    throw InputError("options." + std::string(row.name) + ": value index must be in [0, " +
                     std::to_string(row.count - 1) + "], got " + std::to_string(index));
}

}  // namespace

std::span<const OptionInfo> rows() { return kRows; }

std::size_t indexOf(std::string_view name) {
  for (std::size_t i = 0; i < kRows.size(); ++i)
    if (name == kRows[i].name) return i;
  throw InputError("options: no option named '" + std::string(name) + "'");
}

std::string_view unitOf(const OptionInfo& row, int index) {
  const std::string_view unit = row.unit;
  if (unit != "mm|deg") return unit;
  return index < 3 ? "mm" : "deg";
}

std::string fieldName(const OptionInfo& row, int index) {
  std::string name = "options." + std::string(row.name);
  if (row.type == OptionType::axes)
    name += "[" + std::to_string(index) + "] (" + kAxisNames[static_cast<std::size_t>(index)] + ")";
  return name;
}

double get(const SensorOptions& o, std::size_t option, int index) {
  requireIndex(kRows.at(option), index);
  return kAccess[option].get(o, index);
}

void set(SensorOptions& o, std::size_t option, int index, double value) {
  const OptionInfo& row = kRows.at(option);
  requireIndex(row, index);
  const std::string field = fieldName(row, index);
  if (row.type != OptionType::real && row.type != OptionType::axes) requireWhole(field, value);
  requireInRange(field, value, row.min, row.max, unitOf(row, index));
  kAccess[option].set(o, index, value);
}

void validate(const SensorOptions& o) {
  for (std::size_t i = 0; i < kRows.size(); ++i) {
    const OptionInfo& row = kRows[i];
    for (int k = 0; k < row.count; ++k)
      requireInRange(fieldName(row, k), kAccess[i].get(o, k), row.min, row.max, unitOf(row, k));
  }
  requireBelow("options.release_mm", o.release_mm, "press_mm", o.press_mm);
}

}  // namespace onetip::option_table
