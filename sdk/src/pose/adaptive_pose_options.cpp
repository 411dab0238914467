#include "pose/adaptive_pose_options.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/option_checks.hpp"
#include "core/rotation.hpp"

namespace onetip::pose {

namespace {

void requireIn(double v, double lo, double hi, const char* name, const char* unit) {
  requireInRange(std::string("pose options: ") + name, v, lo, hi, unit);
}

}  // namespace

void AdaptivePoseOptions::validate() const {
  solver.validate();
  self.validate();
  uncertainty.validate();
  requireIn(slip_sigmas, 3, 1000, "slip_sigmas", "");
  requireIn(robust_sigmas, 1, 1000, "robust_sigmas", "");
  requireIn(rotation_significance, 0, 100, "rotation_significance", "");
  requireIn(min_rotation_spread_pitches, 0.05, 5, "min_rotation_spread_pitches", "");
  requireIn(thin_turn_significance, 0, 100, "thin_turn_significance", "");
  requireIn(thin_rigidity_sigmas, 0, 100, "thin_rigidity_sigmas", "");
  requireIn(stick_hold_s, 0.001, 10, "stick_hold_s", "s");
  requireIn(stick_hold_min_frames, 1, 1000, "stick_hold_min_frames", "");
  requireIn(min_macro_markers, 1, 10000, "min_macro_markers", "");
  requireIn(min_thin_stick_markers, 1, 10000, "min_thin_stick_markers", "");
  requireIn(restick_fraction, 0.05, 1, "restick_fraction", "");
  requireIn(macro_window_s, 0.01, 2, "macro_window_s", "s");
  requireIn(macro_drift_pitches, 0.001, 2, "macro_drift_pitches", "");
  requireIn(macro_drift_ratio, 0.05, 0.95, "macro_drift_ratio", "");
  requireIn(macro_tilt_gate_deg, 0.01, 90, "macro_tilt_gate_deg", "deg");
  requireIn(macro_size_change, 0.01, 10, "macro_size_change", "");
  requireIn(macro_confirm_s, 0.001, 1, "macro_confirm_s", "s");
  requireIn(macro_exit_lag_pitches, 0.001, 2, "macro_exit_lag_pitches", "");
  requireIn(max_speed_mm_s, 1, 10000, "max_speed_mm_s", "mm/s");
  requireIn(max_rate_deg_s, 1, 100000, "max_rate_deg_s", "deg/s");
}

EstimatorThresholds deriveThresholds(const AdaptivePoseOptions& o, const SensorSelf& self) {
  EstimatorThresholds t;
  // The noise measured at rest is the frame-to-frame jitter only; under
  // deformation the front end's error also holds a bias that changes with the
  // local shear and perspective (0.0006 mm per axis at default image quality,
  // docs/pose/README.md, against 0.0002-0.0004 mm of jitter at rest). So the
  // measurement can raise the thresholds above the prior, never lower them;
  // and a front end never localises a corner better than ~1e-4 of the pitch.
  t.noise_mm = std::max({self.noise_mm, o.self.prior_noise_mm, 1e-4 * self.pitch_mm});
  t.slip_mm = o.slip_sigmas * t.noise_mm;
  t.robust_mm = o.robust_sigmas * t.noise_mm;
  t.min_spread_mm = o.min_rotation_spread_pitches * self.pitch_mm;
  t.macro_drift_mm = o.macro_drift_pitches * self.pitch_mm;
  t.macro_exit_lag_mm = o.macro_exit_lag_pitches * self.pitch_mm;
  const double dt = self.frame_s;
  t.stick_hold_frames = std::max(o.stick_hold_min_frames, static_cast<int>(std::ceil(o.stick_hold_s / dt - 1e-9)));
  t.window_frames = std::max(2, static_cast<int>(std::lround(o.macro_window_s / dt)));
  t.confirm_frames = std::max(2, static_cast<int>(std::lround(o.macro_confirm_s / dt)));
  t.max_step_mm = o.max_speed_mm_s * dt;
  t.max_step_rad = o.max_rate_deg_s * dt * kRadPerDeg;
  t.frame_s = dt;
  return t;
}

}  // namespace onetip::pose
