// input/gel_recovery.hpp — a gel that recovers after the finger has left is
// not a finger: the contact ends when the finger leaves, not when the pad has
// finished recovering, and a recovering pad starts no contact.
//
// A viscoelastic pad (a standard linear solid) holds, besides the elastic
// field of the finger pressing now, a delayed part v that the finger's past
// load built up. Once no finger loads the pad, v obeys dv/dt = -v / tau_c
// at every marker with one time constant, so between two frames dt apart
//   u_k = alpha u_{k-1},   alpha = exp(-dt / tau_c) in (0, 1)
// (u_i = p_i - r_i against the kept rest, S, mm): the whole field shrinks in
// proportion, monotonically, towards the rest. A finger's field does not: it
// changes shape as the finger moves, holds still (alpha = 1) or grows.
//
// The pair test, over the markers valid in both frames:
//   alpha = <u_{k-1}, u_k> / <u_{k-1}, u_{k-1}> (least squares), and with the
//   marker noise sigma (per axis, its noisiest: pose/sensor_self_model.hpp's
//   largest_axis_noise_mm, the depth through a stereo pair) each residual
//   u_i,k - alpha u_i,k-1 has per-axis sd s = sigma sqrt(1 + alpha^2), alpha
//   has sd s / |u_{k-1}|; worst = max_i |residual_i| / s;
//   shrinking: alpha below 1 by more than fit_sigmas of its sd.
// The frames since the finger's field left: in contact, the last pair that
// shrank and was no scaled copy (worst above the noise bound below) changed
// the field's shape; it ends on u_j. A change beyond release_factor x
// fit_sigmas is the finger's own field going and arms the release; a later,
// smaller one (the last of the finger's field leaving) moves j on; a change
// that does not shrink (a finger pressing or moving) disarms it. While armed,
// frame k = j + n is tested against u_j: alpha_n = <u_j, u_k> / <u_j, u_j>
// must shrink beyond fit_sigmas of its sd with every residual within the
// bound that the largest of N noise residuals (three unit-normal components
// each) passes with probability release_false_alarm (noiseMaximum).
// Release at k = j + 1, the pair right after the change, when besides
//   - the shrink slowed down: alpha exceeds the changing pair's by more than
//     fit_sigmas of their combined sd. A finger leaving takes its elastic
//     field away at the finger's speed; what stays decays at the gel's own
//     rate, exp(-dt / tau_c) per frame, more slowly;
//   - it shrank enough to see a finger that stayed: a finger still holding a
//     field f under a decaying gel leaves a part that does not scale,
//     (1 - alpha) f, so only (1 - alpha) x contact threshold beyond the bound
//     (in units of s) tells a gel alone from a finger still in contact.
// Without the second condition the rule releases fingers that stay, and
// elastic contacts that lift in proportion, early (docs/world/README.md).
// A slow gel at a high frame rate rarely shrinks that much in one frame; its
// frames since j (decayingFrames(), n while every one is a shrinking copy)
// are a recovery seen while the contact holds, and GelCreep measures the gel
// from them (gel_creep.hpp): the whole record inverted with the measured
// constants must leave no elastic field in them, which a finger that stayed
// would. The contact then ends by the contact rule on the finger's own field.
// A finger or a flat plate that lifts while its field keeps its shape also
// shrinks in proportion; it is told apart only when its shrink does not slow
// down where the shape change ends.
// While released, no marker may move away from the rest by more than fit_sigmas s beyond the decay of
// the last frame (max_i |u_i,k| - alpha |u_i,k-1|; looser than the release's bound: it holds the whole
// recovery long), and alpha may not exceed the recovery's mean alpha so far by more than fit_sigmas of
// its sd (sd_alpha sqrt(1 + 1/n) over n frames): a gel recovers at its own constant rate, and a shrink
// that slows or stops is held by a finger. The first frame that breaks this holds a finger (a new
// touch, or one that never left, judged by the contact rule as usual). A finger still brushing the pad
// as it leaves only takes deformation away faster, and stays released. The recovery is over when the
// field is within the contact threshold, where the contact rule alone says "no contact" and the rest
// keeper takes over what is left.
// A finger that touches the gel while it recovers (a press that begins
// before the last one has gone) presses on a surface that keeps rising: the
// markers under it move by the finger's motion plus the rest of the recovery.
// That rest is known: the recovery went on as u_k = alpha u_{k-1} with the
// mean alpha of the frames it was seen alone, so from the last such frame on,
// alpha^n times its field is taken away from the markers (advance(),
// withoutRemainder()) until that contact ends. The new creep the new press
// itself causes is not modelled (the pad's creep gain is not measured).
// All bounds are multiples of the measured noise or noise probabilities; none
// is in mm or frames. On an elastic pad a lift-off leaves nothing to decay.
#pragma once

#include <cstdint>
#include <vector>

#include "contact/contact_field.hpp"
#include "core/marker_field.hpp"

namespace onetip::input {

struct GelRecoveryOptions {
  bool enabled = true;
  double fit_sigmas = 8;              // [3, 100] noise sigmas: a proportional copy, a scale that differs from 1
  double release_factor = 3;          // [1, 100] x fit_sigmas: the shape change of the frame the finger left in
  double release_false_alarm = 1e-3;  // [1e-9, 0.1] per frame: chance that noise alone breaks a release's fit
  void validate() const;              // throws InputError naming the bad field
};

// One frame pair under the test above (exposed for tests and tools).
struct DecayPair {
  bool measured = false;           // enough markers and a field to scale
  double alpha = 0;                // least-squares scale of the last field onto this one
  double alpha_sd = 0;             // its standard deviation
  double worst_sigmas = 0;         // the largest residual in units of its sd s
  double worst_growth_sigmas = 0;  // the largest |u_i,k| - alpha |u_i,k-1|, in units of s
  int markers = 0;                 // markers in the fit
};

// The bound b that the largest of `markers` residuals, each with three independent N(0, 1) components, exceeds
// with probability false_alarm (N P(|r| > b) = false_alarm).
double noiseMaximum(int markers, double false_alarm);

// The pair (before, now) of displacement fields (S, mm per marker, against the rest) over the markers valid in
// both.
DecayPair decayPair(const std::vector<Eigen::Vector3d>& before, const std::vector<std::uint8_t>& before_valid,
                    const std::vector<Eigen::Vector3d>& now, const std::vector<std::uint8_t>& now_valid,
                    double noise_mm);

class GelRecovery {
 public:
  explicit GelRecovery(GelRecoveryOptions options = {});
  // `field` this frame's contact analysis; `was_in_contact` the tracker's last frame; noise_mm the measured
  // marker noise. True when this frame's deformation is the gel recovering alone: not a contact.
  bool recovering(const contact::ContactField& field, bool was_in_contact, double noise_mm,
                  double contact_threshold_mm);
  // What is left of a recovery that a finger interrupted (S, mm per marker; empty when none), advanced by one
  // frame: call once per frame before the analysis. The contact analysis and the pose take it away from the
  // markers, so the new press is measured from where the finger moves them, not where the gel rises to.
  const std::vector<Eigen::Vector3d>& advance();
  // recovering() found a finger on the recovering gel this frame: the remainder began (the frame was analysed
  // without it and is to be analysed again with it taken away).
  bool remainderBegan() const { return remainder_began_; }
  const std::vector<Eigen::Vector3d>& remainder() const { return remainder_; }
  // In contact, the frames n since the finger's field left during which the field has decayed as a gel does
  // (every frame a scaled copy of the first, shrinking, more slowly than the field went), whether or not that
  // decay is yet deep enough to release by itself; 0 otherwise. GelCreep measures the gel from them.
  int decayingFrames() const { return decaying_frames_; }
  void reset();

 private:
  GelRecoveryOptions options_;
  std::vector<Eigen::Vector3d> previous_;
  std::vector<std::uint8_t> previous_valid_;
  // The frames since the last pair that shrank and changed shape, armed by one that changed it beyond
  // release_factor x fit_sigmas (the finger's field going).
  struct ReleaseWindow {
    bool armed = false;
    std::vector<Eigen::Vector3d> base;  // u_j, the field the last shape change ended on
    std::vector<std::uint8_t> base_valid;
    double alpha = 0, alpha_sd = 0;  // the arming pair's scale and its sd
    int frames = 0;                  // n, frames since j
  };
  ReleaseWindow window_;
  int decaying_frames_ = 0;
  bool recovering_ = false;
  double rate_sum_ = 0;  // sum and count of the recovery's per-frame scales alpha, for its mean rate
  int rate_count_ = 0;
  std::vector<Eigen::Vector3d> remainder_;  // the interrupted recovery, as of this frame
  double remainder_alpha_ = 0;              // its per-frame scale: the recovery's mean alpha
  bool remainder_began_ = false;
};

// `now` with the remainder of a recovery taken away from its markers (unchanged when there is none).
MarkerField withoutRemainder(const MarkerField& now, const std::vector<Eigen::Vector3d>& remainder);

// The field with its contact taken away (a recovering gel): no regions, not in contact.
void clearContact(contact::ContactField& field);

}  // namespace onetip::input
