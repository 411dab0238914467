// pipeline/open_pipeline.hpp — a Pipeline from the user's strings: a frame
// source specification, calibration and pattern files and an optional
// rest-state image. Shared by the public API (onetip::Sensor) and the
// `onetip spnav` / `onetip joystick` commands.
//
// Sources: capture/open_frame_source.hpp ("v4l2:/dev/videoN", a folder, a
// video file, "sim:SCENARIO.yaml"; the "sim" scheme is registered here).
// For "sim:" sources an empty calibration and pattern mean the simulator's own
// exact ones (sim::Simulator::calibration()/pattern()); other sources need
// both files. The reference image is read as 8-bit grey.
// Throws InputError naming the source, the file or the option.
#pragma once

#include <memory>
#include <string>
#include <utility>

#include "capture/frame_source.hpp"
#include "pipeline/pipeline.hpp"

namespace onetip::pipeline {

struct PipelineSpec {
  std::string source;
  std::string calibration;  // may be empty for "sim:" sources
  std::string pattern;      // may be empty for "sim:" sources
  std::string reference;    // optional rest-state image
};

std::unique_ptr<Pipeline> openPipeline(const PipelineSpec& spec, const PipelineOptions& options = {});

// The calibration and pattern for `source` (opened from the specification
// `spec`): both files, or for a "sim:" source neither (the simulator's own).
// checkRigFiles throws when only one of the two files is given.
void checkRigFiles(const std::string& calibration, const std::string& pattern);
std::pair<StereoCalibration, MarkerPattern> loadRig(const std::string& calibration, const std::string& pattern,
                                                    const capture::FrameSource& source, const std::string& spec);

}  // namespace onetip::pipeline
