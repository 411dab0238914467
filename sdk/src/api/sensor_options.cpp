#include "onetip/sensor_options.hpp"

#include "api/public_error.hpp"
#include "core/option_table.hpp"
#include "pipeline/options_io.hpp"

namespace onetip {

void SensorOptions::validate() const {
  api::withPublicErrors([&] { option_table::validate(*this); });
}

SensorOptions SensorOptions::load(const std::string& path) {
  return api::withPublicErrors([&] { return pipeline::loadSensorOptions(path); });
}

void SensorOptions::save(const std::string& path) const {
  api::withPublicErrors([&] { pipeline::saveSensorOptions(*this, path); });
}

std::span<const OptionInfo> SensorOptions::table() { return option_table::rows(); }

double SensorOptions::get(std::string_view name, int index) const {
  return api::withPublicErrors([&] { return option_table::get(*this, option_table::indexOf(name), index); });
}

void SensorOptions::set(std::string_view name, double value, int index) {
  api::withPublicErrors([&] { option_table::set(*this, option_table::indexOf(name), index, value); });
}

}  // namespace onetip
