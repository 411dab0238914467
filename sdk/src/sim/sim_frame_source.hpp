// sim/sim_frame_source.hpp — the simulator as a camera: "sim:SCENARIO.yaml".
//
// registerSimFrameSource() teaches capture::openFrameSource the "sim:" scheme,
// so every command or API that takes a frame source also takes a scenario.
// Frames are the simulator's rendered 1920x1080 grey images, timestamped with
// the scenario time (s).
#pragma once

#include <memory>

#include "capture/frame_source.hpp"
#include "sim/simulator.hpp"

namespace onetip::sim {

class SimFrameSource : public capture::FrameSource {
 public:
  explicit SimFrameSource(const std::string& scenario_path);
  capture::Frame next() override;
  std::string describe() const override { return "sim:" + path_; }
  const Simulator& simulator() const { return *sim_; }

 private:
  std::string path_;
  std::unique_ptr<Simulator> sim_;
};

// Idempotent; call once before openFrameSource() sees "sim:..." specs.
void registerSimFrameSource();

}  // namespace onetip::sim
