#include "onetip/sensor_options.hpp"

#include "api/conversions.hpp"
#include "api/public_error.hpp"
#include "pipeline/options_io.hpp"

namespace onetip {

void SensorOptions::validate() const {
  api::withPublicErrors([&] { api::toPipelineOptions(*this).validate(); });
}

SensorOptions SensorOptions::load(const std::string& path) {
  return api::withPublicErrors([&] { return api::toSensorOptions(pipeline::loadPipelineOptions(path)); });
}

void SensorOptions::save(const std::string& path) const {
  api::withPublicErrors([&] { pipeline::savePipelineOptions(api::toPipelineOptions(*this), path); });
}

}  // namespace onetip
