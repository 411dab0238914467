// pose/adaptive_pose_options.hpp — the pose estimator's options and the
// thresholds that follow from them and from what the sensor measures about
// itself (pose/sensor_self_model.hpp: marker noise sigma, pattern pitch p,
// frame interval dt). No option is a length in mm or a count of frames tuned
// at one operating point: each is a multiple of sigma or p, a time in
// seconds, a physical speed, an angle or a ratio.
//
// sigma = max(noise measured at rest, the prior noise of the front end under
// deformation, 1e-4 p): the jitter at rest misses the deformation-dependent
// part of the front end's error, so a measurement only ever raises it.
//   slip threshold   = slip_sigmas * sigma              (drift of an anchored marker, mm)
//   robust scale     = robust_sigmas * sigma            (Cauchy scale of the stick fit, mm)
//   min spread       = min_rotation_spread_pitches * p  (smaller stick sets: no general rotation)
//   stick hold       = max(stick_hold_min_frames, ceil(stick_hold_s / dt)) frames (quiet frames before
//                      a marker sticks again: both a time and a count of quiet measurements; at 15 fps
//                      5 frames of evidence let the twist's slipping ring stick again too early)
//   window           = max(2, round(macro_window_s / dt)) frames (footprint tests)
//   confirm          = max(2, round(macro_confirm_s / dt)) frames (a footprint drift seen this long)
//   drift floor      = macro_drift_pitches * p          (footprint drift that can mean a slide, mm)
//   exit lag         = macro_exit_lag_pitches * p       (footprint lag that ends macroscopic slip, mm)
//   max step         = max_speed_mm_s * dt mm and max_rate_deg_s * dt deg per frame
// The defaults give the thresholds the estimator was tuned with at the front
// end's 0.0006 mm, 1.2 mm pitch and 30 fps (slip 0.01 mm, robust 0.005 mm,
// spread 0.6 mm, hold 10 frames, window 5 frames, confirm 2 frames, drift
// 0.08 mm, exit lag 0.06 mm, 1.5 mm / 6 deg per frame), so the single-axis figures stay where
// they were; at other noise levels, densities and frame rates they scale.
#pragma once

#include <cstdint>

#include "pose/pose_uncertainty.hpp"
#include "pose/sensor_self_model.hpp"
#include "pose/stick_slip_solver.hpp"

namespace onetip::pose {

// adaptive: the estimator (pose/adaptive_pose_estimator.hpp). The others force
// one model for every frame (for comparisons): kabsch_only is the paper's
// Eq. 1 between consecutive frames over all region markers; stick_slip_only
// runs Ceres even at full stick; centroid_only uses the footprint throughout.
// weighted: one objective with stick weights (pose/weighted_pose_estimator.hpp).
enum class ModelPolicy : std::uint8_t { adaptive = 0, kabsch_only, stick_slip_only, centroid_only, weighted };

struct AdaptivePoseOptions {
  StickSlipSolverOptions solver;
  ModelPolicy policy = ModelPolicy::adaptive;
  SensorSelfOptions self;                     // priors until the sensor has measured itself
  PoseUncertaintyOptions uncertainty;         // the motion prior and model error of the reported sd
  double slip_sigmas = 16.7;                  // [3, 1000]
  double robust_sigmas = 8.3;                 // [1, 1000]
  double rotation_significance = 1.0;         // [0, 100] noise sigmas a rotation must reach to be applied
  double min_rotation_spread_pitches = 0.5;   // [0.05, 5]
  // [0, 100] noise sigmas: a stick set narrower than the min spread still fixes a general rotation when its
  // turn about its own line reaches this many sigmas of that turn's noise and it moves rigidly to within
  // thin_rigidity_sigmas (pose/anchored_fit.hpp). A twist's slipping edge stripe fakes a tilt of 2-3 of those
  // sigmas. Lower bars fail measured cases: at 3 and 3 FailurePoints.AContactBeginsWhenOneMarkerPassesTheThreshold,
  // at 5 and 4 a plate pressed edge first is read 0.7 deg RMS off in pitch (decision record 0008, docs/decisions).
  double thin_turn_significance = 5.0;
  double thin_rigidity_sigmas = 3.0;          // [0, 100]
  double stick_hold_s = 0.33;                 // [0.001, 10] s
  int stick_hold_min_frames = 10;             // [1, 1000] quiet measurements, whatever the frame rate
  int min_macro_markers = 15;                 // [1, 10000] smaller regions never declare macroscopic slip
  // [1, 10000] a stick set that fixes no general rotation alone gets Eq. 13-15 (the slip markers' normal
  // residuals fix the rest) only with this many markers: the last 2-3 stuck markers as gross slip
  // begins are often creeping, and trusting them as the stick half of Ceres hides the slide behind a
  // rotation (with 3, gross slip in a 6 mm slide is declared late; decision record 0008, docs/decisions).
  // On a contact too small to declare macroscopic slip, fewer will do once each has been in the contact
  // for the stick hold (thinStickSetTrusted, model_selection.hpp).
  int min_thin_stick_markers = 4;
  // [0.05, 1] of the contact's markers measured over the window that must move as one rigid body
  // (and carry the footprint) before a stick model takes over again from the footprint: at a
  // reversal the whole contact sticks again, in gross slip a few saturated markers can look rigid.
  double restick_fraction = 0.5;
  double macro_window_s = 0.16;               // [0.01, 2] s
  double macro_drift_pitches = 0.067;         // [0.001, 2]
  double macro_drift_ratio = 0.35;            // [0.05, 0.95] of the footprint's own travel (and of the rolling
                                              // shift, in the way back's footprint test)
  double macro_tilt_gate_deg = 1.5;           // [0.01, 90] no decision while the finger tilts this much in the window
  // [0.01, 10] no decision while the region size changes this fraction in the window, nor while the normal
  // deformation under the footprint deepens by it (a plate over the whole pattern cannot grow its region, but
  // its footprint centre moves as it presses deeper)
  double macro_size_change = 0.3;
  // [0.001, 1] s the drift must be seen in consecutive frames (at least two): a time, not a count; at
  // 188 fps two frames are 11 ms, in which a coarse footprint still moves as a press ends and would be
  // taken for a slide
  double macro_confirm_s = 0.067;
  double macro_exit_lag_pitches = 0.05;       // [0.001, 2]
  double max_speed_mm_s = 45;                 // [1, 10000] fastest finger motion followed in one frame
  double max_rate_deg_s = 180;                // [1, 100000]
  void validate() const;                      // throws InputError naming the bad field
};

struct EstimatorThresholds {
  double noise_mm = 0, slip_mm = 0, robust_mm = 0, min_spread_mm = 0, macro_drift_mm = 0, macro_exit_lag_mm = 0;
  int stick_hold_frames = 1, window_frames = 2, confirm_frames = 2;
  double max_step_mm = 0, max_step_rad = 0;
  double frame_s = 1.0 / 30;  // the frame interval (s)
};

EstimatorThresholds deriveThresholds(const AdaptivePoseOptions& options, const SensorSelf& self);

}  // namespace onetip::pose
