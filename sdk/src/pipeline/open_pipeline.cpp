#include "pipeline/open_pipeline.hpp"

#include <opencv2/imgcodecs.hpp>

#include "capture/open_frame_source.hpp"
#include "core/error.hpp"
#include "sim/sim_frame_source.hpp"

namespace onetip::pipeline {

std::unique_ptr<Pipeline> openPipeline(const PipelineSpec& spec, const PipelineOptions& options) {
  options.validate();
  if (spec.source.empty()) throw InputError("source: empty (a folder, a video file, v4l2:/dev/videoN or sim:SCENARIO.yaml)");
  if (spec.calibration.empty() != spec.pattern.empty())
    throw InputError(std::string(spec.calibration.empty() ? "calibration" : "pattern") +
                     ": missing (give both the calibration and the pattern file, or neither for a sim: source)");
  sim::registerSimFrameSource();
  std::unique_ptr<capture::FrameSource> source = capture::openFrameSource(spec.source);
  StereoCalibration calib;
  MarkerPattern pattern;
  if (spec.calibration.empty()) {
    const auto* sim_source = dynamic_cast<const sim::SimFrameSource*>(source.get());
    if (!sim_source)
      throw InputError(spec.source + ": a calibration and a pattern file are needed (only sim: sources have defaults)");
    calib = sim_source->simulator().calibration();
    pattern = sim_source->simulator().pattern();
  } else {
    calib = loadCalibration(spec.calibration);
    pattern = loadPattern(spec.pattern);
  }
  auto pipeline = std::make_unique<Pipeline>(std::move(source), calib, pattern, options);
  if (!spec.reference.empty()) {
    const cv::Mat grey = cv::imread(spec.reference, cv::IMREAD_GRAYSCALE);
    if (grey.empty()) throw InputError(spec.reference + ": not a readable image");
    try {
      pipeline->setReference(grey);
    } catch (const InputError& e) {
      throw InputError(spec.reference + ": cannot be the rest state: " + e.what());
    }
  }
  return pipeline;
}

}  // namespace onetip::pipeline
