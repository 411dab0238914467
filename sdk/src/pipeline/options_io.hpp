// pipeline/options_io.hpp — PipelineOptions to and from an options file
// (read as YAML or JSON by core/config_file.hpp, written as YAML), with the user-facing key names of
// onetip/sensor_options.hpp:
//   queue_capacity, lossless (0/1), playback_rate, event_queue_capacity,
//   frame_queue_capacity, timing_window, max_consecutive_source_errors,
//   stop_timeout_ms, min_markers, working_range [dx dy dz yaw pitch roll]
//   (mm, deg), clamp_factor, press_mm, release_mm, gain [6], dead_zone [6],
//   filter ("none" | "moving_average" | "one_euro"), filter_window,
//   filter_min_cutoff_hz, filter_beta, filter_derivative_cutoff_hz.
// Loading starts from `base` (the defaults), overrides the keys present and
// rejects unknown keys, wrong types and values the options refuse with an
// InputError naming the file, the line and the key. Processor settings without a key here (detector,
// tracker, triangulator, contact and pose solver tuning) keep `base`'s values.
// Saving writes every key, atomically.
#pragma once

#include <string>

#include "pipeline/pipeline.hpp"

namespace onetip::pipeline {

PipelineOptions loadPipelineOptions(const std::string& path, const PipelineOptions& base = {});
void savePipelineOptions(const PipelineOptions& options, const std::string& path);

}  // namespace onetip::pipeline
