// tools/pipeline_command.hpp — what the commands that serve the pipeline's
// output to other programs (`onetip spnav`, `onetip joystick`) share: the
// input options, opening the pipeline, and running it until SIGINT/SIGTERM or
// the end of the source.
//
// Options: --input SRC (required), --calib C --pattern P (both, or neither for
// sim: sources), --reference IMG, --options OPTIONS.yaml (onetip/sensor_options.hpp
// keys; e.g. `lossless: 1` to process every frame of a file or scenario).
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "command.hpp"
#include "interrupt.hpp"
#include "pipeline/pipeline.hpp"

namespace onetip::tools {

std::vector<OptionSpec> pipelineInputOptions();
// The options of --options (defaults without it).
pipeline::PipelineOptions pipelineOptionsFromArgs(const Args& args);
std::unique_ptr<pipeline::Pipeline> openPipelineFromArgs(const Args& args);
std::unique_ptr<pipeline::Pipeline> openPipelineFromArgs(const Args& args, const pipeline::PipelineOptions& options);

// Starts `p`, waits until SIGINT/SIGTERM (handlers installed for the call) or
// the source ends, then stops it. `ready` runs after the handlers are in place
// and before start (e.g. to wait for a first client); returning false stops
// without starting. Prints a one-line summary to stderr (skipped frames
// included). Returns 0, 130 after an interrupt, or 1 when most frames were
// unreadable (frame_tally.hpp).
int runPipelineUntilInterrupted(pipeline::Pipeline& p, const std::function<bool()>& ready = {});

}  // namespace onetip::tools
