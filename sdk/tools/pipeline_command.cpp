#include "pipeline_command.hpp"

#include <cstdio>

#include "frame_tally.hpp"
#include "interrupt.hpp"
#include "pipeline/open_pipeline.hpp"
#include "pipeline/options_io.hpp"

namespace onetip::tools {

std::vector<OptionSpec> pipelineInputOptions() {
  return {{"input", "frames: a folder of images, a video file, v4l2:/dev/videoN or sim:SCENARIO.yaml", false, true},
          {"calib", "calibration file (docs/reference.md); optional for sim: sources", false, false},
          {"pattern", "marker pattern file; optional for sim: sources", false, false},
          {"reference", "rest-state image (default: the first frame)", false, false},
          {"options", "pipeline options file (YAML, keys of onetip/sensor_options.hpp)", false, false}};
}

pipeline::PipelineOptions pipelineOptionsFromArgs(const Args& args) {
  pipeline::PipelineOptions options;
  if (auto path = args.optional("options")) options = pipeline::loadPipelineOptions(*path);
  return options;
}

std::unique_ptr<pipeline::Pipeline> openPipelineFromArgs(const Args& args, const pipeline::PipelineOptions& options) {
  return pipeline::openPipeline({args.get("input"), args.optional("calib").value_or(""),
                                 args.optional("pattern").value_or(""), args.optional("reference").value_or("")},
                                options);
}

std::unique_ptr<pipeline::Pipeline> openPipelineFromArgs(const Args& args) {
  return openPipelineFromArgs(args, pipelineOptionsFromArgs(args));
}

int runPipelineUntilInterrupted(pipeline::Pipeline& p, const std::function<bool()>& ready) {
  InterruptHandlers handlers;
  if (ready && !ready()) return interruptRequested() ? kInterruptedExit : 0;
  p.start();
  while (!interruptRequested() && !p.waitFinished(0.05)) {
  }
  p.stop();
  const pipeline::PipelineStats s = p.stats();
  std::fprintf(stderr, "%s: %lld frames processed, %lld skipped (%lld unreadable), %lld dropped, %lld lost, %lld source errors\n",
               interruptRequested() ? "interrupted" : "source ended", static_cast<long long>(s.frames_processed),
               static_cast<long long>(s.frames_skipped), static_cast<long long>(s.frames_unreadable),
               static_cast<long long>(s.frames_dropped), static_cast<long long>(s.frames_lost),
               static_cast<long long>(s.source_errors));
  if (interruptRequested()) return kInterruptedExit;
  const long long unreadable = s.frames_unreadable + s.source_errors;
  return unreadableFramesExit("onetip", unreadable, s.frames_captured + unreadable);
}

}  // namespace onetip::tools
