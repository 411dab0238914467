// sim/camera_shift.hpp — the camera (or one mirror) shifting against the pad:
// a bumped mount, thermal creep of the housing, a camera mode that crops the
// frame elsewhere. The whole view moves in the image, the pad does not.
//
// The shift of the delivered frame's pixels (x right, y down, after the
// mirror flip; px) at time t (s):
//   s(t) = shift_px * clamp((t - at_s) / ramp_s, 0, 1)   (ramp_s > 0: a slow ramp)
//   s(t) = shift_px * [t >= at_s]                         (ramp_s = 0: a step)
// applied to both views (`view: both`, the camera moved) or to one
// (`left` | `right`, its mirror moved). The renderer moves the view's
// principal point by s (by -s_x along x where the view is mirrored), so every
// rendered point, corners included, moves by exactly s whatever the lens
// distortion; the image edges show the housing, as a real crop would.
// Field level: none. The marker field (gt_markers.csv) is the pad itself,
// which did not move; the apparent motion a tracker reads from a shifted
// image is a measurement error to be recognised by the SDK, not part of the
// truth, and a field-level run has no camera to shift.
#pragma once

#include <Eigen/Core>
#include <string_view>

namespace onetip::sim {

struct CameraShiftOptions {
  Eigen::Vector2d shift_px = Eigen::Vector2d::Zero();  // final shift, each component -100..100 px
  double at_s = 0;                                     // when it starts, 0..3600 s
  double ramp_s = 0;                                   // 0: a step; else its duration, 0..3600 s
  enum class Views { both, left, right } views = Views::both;
  bool enabled() const { return !shift_px.isZero(0); }
  // The shift of view i (0 left, 1 right) at time t, in delivered-frame pixels.
  Eigen::Vector2d shiftAt(double t, int view) const;
  void validate() const;                               // throws InputError naming the bad field
};

// "both" | "left" | "right"; false for anything else.
bool cameraShiftViewsFromString(std::string_view name, CameraShiftOptions::Views& out);

}  // namespace onetip::sim
