// The options functions of the C ABI: the struct, the option table and keyed
// access, all through the public SensorOptions (whose table is
// onetip/sensor_option_table.hpp).
#include "c_options.hpp"

#include <algorithm>
#include <string>
#include <type_traits>

#include "c_structs.hpp"

namespace onetip::c_api {
namespace {

// Calls fn(option, C field) for every option; S and C are SensorOptions and
// onetip_options, either of them const.
template <typename S, typename C, typename Fn>
void forEachCField(S& s, C& c, Fn&& fn) {
  fn(s.queue_capacity, c.queue_capacity);
  fn(s.lossless, c.lossless);
  fn(s.playback_rate, c.playback_rate);
  fn(s.event_queue_capacity, c.event_queue_capacity);
  fn(s.frame_queue_capacity, c.frame_queue_capacity);
  fn(s.timing_window, c.timing_window);
  fn(s.max_consecutive_source_errors, c.max_consecutive_source_errors);
  fn(s.stop_timeout_ms, c.stop_timeout_ms);
  fn(s.min_markers, c.min_markers);
  fn(s.working_range, c.working_range);
  fn(s.clamp_factor, c.clamp_factor);
  fn(s.press_mm, c.press_mm);
  fn(s.release_mm, c.release_mm);
  fn(s.gain, c.gain);
  fn(s.dead_zone, c.dead_zone);
  fn(s.filter, c.filter);
  fn(s.filter_window, c.filter_window);
  fn(s.filter_min_cutoff_hz, c.filter_min_cutoff_hz);
  fn(s.filter_beta, c.filter_beta);
  fn(s.filter_derivative_cutoff_hz, c.filter_derivative_cutoff_hz);
}

static_assert(ONETIP_FILTER_NONE == static_cast<int>(FilterKind::none) &&
              ONETIP_FILTER_MOVING_AVERAGE == static_cast<int>(FilterKind::moving_average) &&
              ONETIP_FILTER_ONE_EURO == static_cast<int>(FilterKind::one_euro));

void copyValue(AxisArray& to, const double (&from)[6]) { std::copy(std::begin(from), std::end(from), to.begin()); }
void copyValue(double (&to)[6], const AxisArray& from) { std::copy(from.begin(), from.end(), to); }
template <typename To, typename From>
void copyValue(To& to, const From& from) {
  if constexpr (std::is_enum_v<To> || std::is_enum_v<From> || std::is_same_v<To, bool> || std::is_same_v<From, bool>)
    to = static_cast<To>(static_cast<int>(from));
  else
    to = from;
}

onetip_option_info describe(const OptionInfo& row) {
  onetip_option_info c{};
  copyString(c.name, sizeof c.name, row.name);
  c.type = static_cast<std::int32_t>(row.type);
  c.count = row.count;
  c.min = row.min;
  c.max = row.max;
  std::copy(row.default_value.begin(), row.default_value.end(), c.default_value);
  copyString(c.unit, sizeof c.unit, row.unit);
  std::string choices;
  for (const char* name : row.choices) choices += (choices.empty() ? "" : " ") + std::string(name);
  copyString(c.choices, sizeof c.choices, choices);
  copyString(c.doc, sizeof c.doc, row.doc);
  return c;
}

}  // namespace

onetip_options toC(const SensorOptions& o) noexcept {
  onetip_options c{};
  forEachCField(o, c, [](const auto& option, auto& field) { copyValue(field, option); });
  return c;
}

SensorOptions fromC(const onetip_options& c, bool validate) {
  // The table's own checks, before the values are squeezed into bool and the enum.
  SensorOptions probe;
  probe.set("lossless", c.lossless);
  probe.set("filter", c.filter);
  SensorOptions o;
  forEachCField(o, c, [](auto& option, const auto& field) { copyValue(option, field); });
  if (validate) o.validate();
  return o;
}

}  // namespace onetip::c_api

using namespace onetip;
using namespace onetip::c_api;

extern "C" {

ONETIP_C_API uint32_t onetip_abi_minor_version(void) { return ONETIP_C_ABI_MINOR_VERSION; }

ONETIP_C_API int32_t onetip_options_default(uint32_t abi_version, onetip_options* out, onetip_error* error) {
  return boundary(error, [&] {
    requireAbiVersion(abi_version);
    requireNonNull(out, "onetip_options_default: out");
    *out = toC(SensorOptions{});
  });
}

ONETIP_C_API int32_t onetip_options_load(uint32_t abi_version, const char* path, onetip_options* out,
                                         onetip_error* error) {
  return boundary(error, [&] {
    requireAbiVersion(abi_version);
    requireNonNull(path, "onetip_options_load: path");
    requireNonNull(out, "onetip_options_load: out");
    *out = toC(SensorOptions::load(path));
  });
}

ONETIP_C_API int32_t onetip_options_save(uint32_t abi_version, const onetip_options* options, const char* path,
                                         onetip_error* error) {
  return boundary(error, [&] {
    requireAbiVersion(abi_version);
    requireNonNull(options, "onetip_options_save: options");
    requireNonNull(path, "onetip_options_save: path");
    fromC(*options).save(path);
  });
}

ONETIP_C_API int32_t onetip_options_validate(uint32_t abi_version, const onetip_options* options, onetip_error* error) {
  return boundary(error, [&] {
    requireAbiVersion(abi_version);
    requireNonNull(options, "onetip_options_validate: options");
    fromC(*options);
  });
}

ONETIP_C_API int32_t onetip_option_count(void) { return static_cast<int32_t>(SensorOptions::table().size()); }

ONETIP_C_API int32_t onetip_option_describe(uint32_t abi_version, int32_t row, onetip_option_info* out,
                                            onetip_error* error) {
  return boundary(error, [&] {
    requireAbiVersion(abi_version);
    requireNonNull(out, "onetip_option_describe: out");
    const auto table = SensorOptions::table();
    if (row < 0 || static_cast<std::size_t>(row) >= table.size())
      throw Error(ErrorKind::input, "onetip_option_describe: row must be in [0, " + std::to_string(table.size() - 1) +
                                        "], got " + std::to_string(row));
    *out = describe(table[static_cast<std::size_t>(row)]);
  });
}

ONETIP_C_API int32_t onetip_options_get(uint32_t abi_version, const onetip_options* options, const char* name,
                                        int32_t index, double* out, onetip_error* error) {
  return boundary(error, [&] {
    requireAbiVersion(abi_version);
    requireNonNull(options, "onetip_options_get: options");
    requireNonNull(name, "onetip_options_get: name");
    requireNonNull(out, "onetip_options_get: out");
    *out = fromC(*options, false).get(name, index);
  });
}

ONETIP_C_API int32_t onetip_options_set(uint32_t abi_version, onetip_options* options, const char* name, int32_t index,
                                        double value, onetip_error* error) {
  return boundary(error, [&] {
    requireAbiVersion(abi_version);
    requireNonNull(options, "onetip_options_set: options");
    requireNonNull(name, "onetip_options_set: name");
    SensorOptions o = fromC(*options, false);
    o.set(name, value, index);
    *options = toC(o);
  });
}

}  // extern "C"
