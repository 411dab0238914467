// viewer/virtual_finger.hpp — a simulated finger driven by mouse and keyboard,
// for people without the hardware: its pose feeds the simulator
// (sim::Simulator::nextPosed), whose rendered frames go through the full
// pipeline like a camera's.
//
// The pose is a scenario keyframe (sim/scenario.hpp): x, y (mm, S), depth
// (mm below the undeformed pad surface; negative: above it), yaw, pitch,
// roll (degrees; R = Rz(yaw) Ry(roll) Rx(pitch) about the finger's tip).
// Each frame's controls are increments; one frame moves at most
// max_step_mm / max_step_deg per axis (the contact model sub-steps anyway,
// this keeps the motion visible and the tracker in range) and the pose stays
// inside the ranges below. lift returns to the rest pose above the pad.
#pragma once

#include <memory>

#include "capture/frame_source.hpp"
#include "sim/scenario.hpp"
#include "sim/simulator.hpp"

namespace onetip::viewer {

struct FingerControls {
  double slide_x = 0, slide_y = 0;       // mm along S.x, S.y
  double press = 0;                      // mm deeper (+) or shallower (-)
  double twist = 0, pitch = 0, roll = 0; // degrees
  bool lift = false;
};

struct VirtualFingerOptions {
  double rest_depth_mm = -0.5;   // lifted: above the pad, no contact
  double max_depth_mm = 3.5;
  double max_offset_mm = 5.0;    // |x|, |y|
  double max_yaw_deg = 20.0;
  double max_tilt_deg = 30.0;    // |pitch|, |roll|
  double max_step_mm = 0.25;     // per frame and axis
  double max_step_deg = 2.0;
  void validate() const;         // throws InputError naming the bad field
};

class VirtualFinger {
 public:
  explicit VirtualFinger(VirtualFingerOptions options = {});
  void apply(const FingerControls& controls);
  const sim::Keyframe& pose() const noexcept { return pose_; }
  const VirtualFingerOptions& options() const noexcept { return options_; }

 private:
  VirtualFingerOptions options_;
  sim::Keyframe pose_;
};

// The virtual finger's scene: the default pad and cameras, one ellipsoid
// finger (7 x 9 x 6 mm semi-axes) lifted above the pad, 60 frames per second.
sim::Scenario virtualFingerScenario();

// The simulated sensor pressed by a VirtualFinger, as a frame source
// ("sim:virtual"): every next() renders the scene with the finger's pose.
class VirtualFingerSource : public capture::FrameSource {
 public:
  explicit VirtualFingerSource(VirtualFingerOptions options = {});
  capture::Frame next() override;
  std::string describe() const override { return "sim:virtual"; }
  VirtualFinger& finger() noexcept { return finger_; }
  const sim::Simulator& simulator() const noexcept { return *sim_; }

 private:
  VirtualFinger finger_;
  std::unique_ptr<sim::Simulator> sim_;
};

}  // namespace onetip::viewer
