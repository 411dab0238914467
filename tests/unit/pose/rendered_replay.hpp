// tests/unit/pose/rendered_replay.hpp — a simulator scenario through the real
// image path: every frame rendered (sim::Simulator::render(), 1920 x 1080
// grey, the scenario's image noise), then pipeline::FrameProcessor (corner
// detection, grid tracking, triangulation, S from the first frame, then the
// PoseTracker), its 6-D output kept next to the simulator's ground truth.
// `fps` > 0 replaces the scenario's frame rate (fewer frames, same motion),
// to keep the rendering time of a test down.
#pragma once

#include "pipeline/frame_processor.hpp"
#include "sim_replay.hpp"

namespace onetip::poseval {

struct RenderedReplay {
  std::vector<ReplayFrame> frames;
  int lost_frames = 0;           // frames the processor could not use
  double marker_rmse_mm[3]{};    // per axis, triangulated markers vs the true ones (S)
};

RenderedReplay replayRendered(sim::Scenario scenario, double fps = 0,
                              const pipeline::FrameProcessorOptions& options = {});

}  // namespace onetip::poseval
