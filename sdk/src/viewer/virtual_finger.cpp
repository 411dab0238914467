#include "viewer/virtual_finger.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace onetip::viewer {

namespace {
// Moves `value` by `step` (limited to +-max_step) and keeps it in [low, high].
double stepped(double value, double step, double max_step, double low, double high) {
  return std::clamp(value + std::clamp(step, -max_step, max_step), low, high);
}
}  // namespace

void VirtualFingerOptions::validate() const {
  if (!(max_depth_mm > 0 && max_depth_mm <= 6)) throw InputError("virtual finger: max_depth_mm: must be in (0, 6]");
  if (!(rest_depth_mm < 0 && rest_depth_mm > -5)) throw InputError("virtual finger: rest_depth_mm: must be in (-5, 0)");
  if (!(max_offset_mm >= 0 && max_offset_mm <= 10)) throw InputError("virtual finger: max_offset_mm: must be in [0, 10]");
  if (!(max_yaw_deg >= 0 && max_yaw_deg <= 45)) throw InputError("virtual finger: max_yaw_deg: must be in [0, 45]");
  if (!(max_tilt_deg >= 0 && max_tilt_deg <= 45)) throw InputError("virtual finger: max_tilt_deg: must be in [0, 45]");
  if (!(max_step_mm > 0)) throw InputError("virtual finger: max_step_mm: must be > 0");
  if (!(max_step_deg > 0)) throw InputError("virtual finger: max_step_deg: must be > 0");
}

VirtualFinger::VirtualFinger(VirtualFingerOptions options) : options_(options) {
  options_.validate();
  pose_.depth = options_.rest_depth_mm;
}

void VirtualFinger::apply(const FingerControls& c) {
  const VirtualFingerOptions& o = options_;
  if (c.lift) {
    pose_ = sim::Keyframe{};
    pose_.depth = o.rest_depth_mm;
    return;
  }
  pose_.x = stepped(pose_.x, c.slide_x, o.max_step_mm, -o.max_offset_mm, o.max_offset_mm);
  pose_.y = stepped(pose_.y, c.slide_y, o.max_step_mm, -o.max_offset_mm, o.max_offset_mm);
  pose_.depth = stepped(pose_.depth, c.press, o.max_step_mm, o.rest_depth_mm, o.max_depth_mm);
  pose_.yaw = stepped(pose_.yaw, c.twist, o.max_step_deg, -o.max_yaw_deg, o.max_yaw_deg);
  pose_.pitch = stepped(pose_.pitch, c.pitch, o.max_step_deg, -o.max_tilt_deg, o.max_tilt_deg);
  pose_.roll = stepped(pose_.roll, c.roll, o.max_step_deg, -o.max_tilt_deg, o.max_tilt_deg);
}

sim::Scenario virtualFingerScenario() {
  sim::Scenario sc;
  sc.name = "virtual";
  sc.description = "A finger moved by mouse and keyboard (onetip view --input sim:virtual).";
  sc.fps = 60;
  sim::IndenterTrack finger;
  finger.keyframes = {sim::Keyframe{}};
  finger.keyframes.front().depth = VirtualFingerOptions{}.rest_depth_mm;
  sc.indenters = {finger};
  return sc;
}

VirtualFingerSource::VirtualFingerSource(VirtualFingerOptions options)
    : finger_(options), sim_(std::make_unique<sim::Simulator>(virtualFingerScenario())) {}

capture::Frame VirtualFingerSource::next() {
  const sim::GroundTruthFrame& g = sim_->nextPosed({finger_.pose()});
  capture::Frame f;
  f.status = capture::FrameStatus::ok;
  f.grey = sim_->render();
  f.index = g.index;
  f.timestamp_s = g.t;
  return count(std::move(f));
}

}  // namespace onetip::viewer
