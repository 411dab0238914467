// pipeline/options_io.hpp — the public SensorOptions (one table:
// onetip/sensor_option_table.hpp) as the pipeline's settings and as an options
// file, both derived from the table.
//
// Conversion: each option feeds one pipeline setting (same units); one field
// map in options_io.cpp serves both directions. Processor settings without an
// option (detector, tracker, triangulator, contact and pose solver tuning)
// keep `base`'s values.
//
// File: read as YAML or JSON by core/config_file.hpp, written as YAML; the keys
// are the table's names, in table order. Loading starts from `base` (the
// defaults), overrides the keys present and rejects unknown keys, wrong types
// and values outside the table's range with an InputError
//   "<file>:<line>: key '<name>': expected a number in [lo, hi], got ..."
// and a value the relations between options refuse (release_mm >= press_mm)
// at its own key. Saving validates, then writes every key, atomically.
#pragma once

#include <string>

#include "onetip/sensor_options.hpp"
#include "pipeline/pipeline.hpp"

namespace onetip::pipeline {

PipelineOptions toPipelineOptions(const SensorOptions& o, const PipelineOptions& base = {});
SensorOptions toSensorOptions(const PipelineOptions& p);

SensorOptions loadSensorOptions(const std::string& path, const SensorOptions& base = {});
void saveSensorOptions(const SensorOptions& o, const std::string& path);
// loadSensorOptions over toSensorOptions(base), then toPipelineOptions(..., base).
PipelineOptions loadPipelineOptions(const std::string& path, const PipelineOptions& base = {});

}  // namespace onetip::pipeline
