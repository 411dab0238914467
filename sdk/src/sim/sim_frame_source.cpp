#include "sim/sim_frame_source.hpp"

#include "capture/open_frame_source.hpp"

namespace onetip::sim {

SimFrameSource::SimFrameSource(const std::string& scenario_path)
    : path_(scenario_path), sim_(std::make_unique<Simulator>(loadScenario(scenario_path))) {}

capture::Frame SimFrameSource::next() {
  capture::Frame f;
  if (sim_->done()) {
    f.status = capture::FrameStatus::end;
    return f;
  }
  const GroundTruthFrame& g = sim_->next();
  f.status = capture::FrameStatus::ok;
  f.grey = sim_->render();
  f.index = g.index;
  f.timestamp_s = g.t;
  return count(std::move(f));
}

void registerSimFrameSource() {
  capture::registerFrameSourceScheme(
      "sim", [](const std::string& rest) { return std::make_unique<SimFrameSource>(rest); });
}

}  // namespace onetip::sim
