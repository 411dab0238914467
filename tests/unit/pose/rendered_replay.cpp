#include "rendered_replay.hpp"

#include <cmath>

#include "sim/simulator.hpp"

namespace onetip::poseval {

RenderedReplay replayRendered(sim::Scenario scenario, double fps, const pipeline::FrameProcessorOptions& options) {
  if (fps > 0) scenario.fps = fps;
  sim::Simulator simulator(std::move(scenario));
  pipeline::FrameProcessor processor(simulator.calibration(), simulator.pattern(), options);
  RenderedReplay out;
  double squares[3]{};
  long markers = 0;
  while (!simulator.done()) {
    const sim::GroundTruthFrame& truth = simulator.next();
    const pipeline::FrameResult r = processor.process(simulator.render(), truth.t);
    if (r.status != pipeline::FrameStatus::ok && r.status != pipeline::FrameStatus::reference) {
      ++out.lost_frames;
      continue;
    }
    for (int i = 0; i < r.markers.size(); ++i) {
      if (!r.markers.valid[static_cast<size_t>(i)]) continue;
      const Eigen::Vector3d e = r.markers.position[static_cast<size_t>(i)] - truth.markers.position[static_cast<size_t>(i)];
      for (int k = 0; k < 3; ++k) squares[k] += e[k] * e[k];
      ++markers;
    }
    out.frames.push_back(replayFrame(truth, r.pose, r.markers.size()));
  }
  for (int k = 0; k < 3; ++k) out.marker_rmse_mm[k] = markers ? std::sqrt(squares[k] / static_cast<double>(markers)) : 0.0;
  return out;
}

}  // namespace onetip::poseval
