// tests/unit/pose/stick_oracle.hpp — what issue 40's objective can reach when
// its stick weights are perfect: the ceiling of registering markers against
// their anchors, whatever finds the weights.
//
// The oracle is told, per frame, which markers truly stick (their node touches
// the followed finger and does not slip: campaign_score.hpp's trulySticks)
// and which touch it and slip, and solves the estimator's own per-frame
// problem (pose/weighted_increment.hpp) with those weights instead of
// estimated ones:
//   - a marker that sticks is anchored on the finger where it first stuck,
//     a_i = T_j^-1 p_i(j) (T_j the oracle's own pose then: the brush model's
//     re-anchoring, so a marker that slipped and sticks again gets a new
//     anchor); it carries the finger (w_i = 1) from the next frame on. The
//     surface point is registered, the marker plus its depth along S.z
//     (decision 0003: the marker layer is the finger's motion conjugated by
//     that offset), so T is the finger's own motion;
//   - a marker that touches and slips stays on the finger's surface: its
//     residual along the measured surface normal (contact/surface_normals.hpp;
//     Eq. 13-15, w_i = 0), unless options.slip_normals is off, with the sd of
//     sliding_surface.hpp (slidingSurfaceSd): the noise and the
//     model error of its slide (the marker layer's departure from the
//     surface), the slide first predicted by the last increment, then taken
//     from a first solve;
//   - what those do not fix comes from a motion prior with the estimator's
//     random walk per frame (PoseUncertaintyOptions), as issue 40 item 2 asks:
//     the motion held (the prior expects no increment), or a rate that decays
//     (it expects the oracle's last increment again, times exp(-dt / tau));
//   - over an interval in which no marker sticks in both frames
//     (observable_truth.hpp) it does what the observable truth does: the turn
//     held, x and y following the true footprint's centroid, z the truth's
//     depth, so those intervals cost the oracle nothing;
//   - with the estimate's labels, where it labels no marker that stuck in the
//     last frame too while some truly does, the footprint (the centroid of the
//     markers that touch the finger in this frame and the last) carries the
//     slide, as the estimator's own footprint term.
// The contact, its onset and c0 are the truth's. So what error it leaves comes from the frames where markers stick:
// their noise and what the sticking and sliding markers do not fix, which no
// estimator with this objective removes however well it finds the weights.
// Two fingers: only the markers whose nodes touch the followed finger count.
#pragma once

#include <vector>

#include "sim_replay.hpp"

namespace onetip::poseval {

// Whose stick labels the oracle registers: the truth's (the ceiling); the
// estimate's own (frames[k].stick as track() left it: what its labels would
// give with everything else as the oracle does it); or those of the
// estimate's labels that are true (its false stick labels removed, its missed
// ones still missed: what the labels' precision alone costs).
// Three more, with the reweighting below: estimate_touching, the estimate's labels on the markers whose
// nodes touch the followed finger (what its labels outside the touch cost); none, no marker labelled
// (frame-to-frame registration by the truncated cost alone); self, the oracle's own (every touched marker
// at onset, then each that carried the finger or moved with it over the last frame: the truncated cost
// with the anchors as its memory).
enum class OracleLabels { truth, estimate, estimate_true, estimate_touching, none, self };

struct StickOracleOptions {
  double noise_mm = 0.0006;  // marker noise per axis (mm), as the recording's
  OracleLabels labels = OracleLabels::truth;
  // The sliding markers' normal residuals on (Eq. 13-15) or off. They fix a tilt that one to four sticking
  // markers cannot, but the lattice normal at a contact's edge is not the finger's (the marker layer bends
  // there), so where the sticking markers fix the motion alone they bias it (decision record 0018).
  bool slip_normals = true;
  // Their sd grows with each marker's slide (sliding_surface.hpp: slidingSurfaceSd, the marker
  // layer's departure from the surface); off: the noise alone, as decision record 0018 measured.
  bool sliding_model_error = true;
  // The motion prior's rate time constant tau (s): 0 holds the motion; tau > 0 expects the last increment
  // again, scaled by exp(-dt / tau) (infinity: a constant rate).
  double prior_rate_tau_s = 0;
  // After the labelled solve, every marker takes its cheapest case under the truncated cost
  // (pose/weighted_increment.hpp: solveByReweighting) and the increment is solved again: a labelled marker
  // whose anchor the motion no longer carries slips and is anchored anew where it is (unlabelled for the
  // frame), and a marker the labels do not carry that moved with the finger over the frame (its anchor is
  // where it was) carries this frame's increment, without gaining an anchor or a label.
  bool reweight = false;
};

// Replaces each frame's estimate (contact, raw, composed, stick labels) by the
// oracle's; the truth fields are kept. `frames` come from track(recording).
void applyStickOracle(const Recording& recording, std::vector<ReplayFrame>& frames,
                      const StickOracleOptions& options = {});

}  // namespace onetip::poseval
