#include "pipeline/open_pipeline.hpp"

#include "capture/image_file.hpp"
#include "capture/open_frame_source.hpp"
#include "core/error.hpp"
#include "sim/sim_frame_source.hpp"

namespace onetip::pipeline {

void checkRigFiles(const std::string& calibration, const std::string& pattern) {
  if (calibration.empty() != pattern.empty())
    throw InputError(std::string(calibration.empty() ? "calibration" : "pattern") +
                     ": missing (give both the calibration and the pattern file, or neither for a sim: source)");
}

std::pair<StereoCalibration, MarkerPattern> loadRig(const std::string& calibration, const std::string& pattern,
                                                    const capture::FrameSource& source, const std::string& spec) {
  checkRigFiles(calibration, pattern);
  if (!calibration.empty()) return {loadCalibration(calibration), loadPattern(pattern)};
  const auto* sim_source = dynamic_cast<const sim::SimFrameSource*>(&source);
  if (!sim_source) throw InputError(spec + ": a calibration and a pattern file are needed (only sim: sources have defaults)");
  return {sim_source->simulator().calibration(), sim_source->simulator().pattern()};
}

std::unique_ptr<Pipeline> openPipeline(const PipelineSpec& spec, const PipelineOptions& options) {
  options.validate();
  if (spec.source.empty()) throw InputError("source: empty (a folder, a video file, v4l2:/dev/videoN or sim:SCENARIO.yaml)");
  checkRigFiles(spec.calibration, spec.pattern);
  sim::registerSimFrameSource();
  std::unique_ptr<capture::FrameSource> source = capture::openFrameSource(spec.source);
  const auto [calib, pattern] = loadRig(spec.calibration, spec.pattern, *source, spec.source);
  const cv::Size frame_size(calib.image_width, calib.image_height);
  auto pipeline = std::make_unique<Pipeline>(std::move(source), calib, pattern, options);
  if (!spec.reference.empty()) {
    const cv::Mat grey = capture::loadGreyImage(spec.reference, frame_size);
    try {
      pipeline->setReference(grey);
    } catch (const InputError& e) {
      throw InputError(spec.reference + ": cannot be the rest state: " + e.what());
    }
  }
  return pipeline;
}

}  // namespace onetip::pipeline
