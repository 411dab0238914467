// input/gel_creep.hpp — a held press on a creeping gel is not a finger
// pressing deeper: the gel's creep is measured from the press itself, by its
// time course and its shape, and taken away from the markers.
//
// The physics (input/creep_model.hpp): on a standard linear solid the markers
// show u = u_e + v (S, mm, against the kept rest), u_e what the finger's pose
// causes now, v the delayed part, dv/dt = (c u_e - v) / tau_c. While the
// finger holds still u_e is constant, so from the frame h it stopped in
//   u_k = (1 + c) u_e - a^(k-h) D,   D = c u_e - v_h,   a = exp(-dt / tau_c):
// the whole field moves along one straight line in field space, by increments
// that are scaled copies of one another shrinking by a per frame, and the
// frame before h is far off that line (the finger was moving). A finger that
// presses deeper on an elastic gel moves the field along a curve: its contact
// widens, the markers it touches move together with the finger instead of in
// proportion to how deep each one already is, and the increments turn.
// Simulator's truth, creep_press (r = 0.3, tau = 1 s: tau_c = 1.43 s, c =
// 0.43) against an elastic twin whose finger presses on with the creep's time
// course (1.5 + 0.4 (1 - exp(-t / tau_c)) mm), marker noise 0.0006 mm: no
// elastic press of the finger is within 0.08-0.25 mm of the creeping field at
// any point of the hold; from the frame the finger stopped, the creep's
// windows stay on one exponential within the noise bound (4.4-4.9 sd against
// 5.7-6.1) and the twin's do not (7.5-12.4 sd), and the frame before the creep's
// is 40-54 sd off it. Later in the twin's press the depth changes too little
// within a window for its curve to show (a 16-frame window from 1.5 s reads
// 4.8 sd): there only the missing stop tells it from a creep.
// Not every indenter tells them apart: a flat punch whose contact does not
// grow with depth moves the field along a straight line too, and its press
// that stops and then slows as exp(-t / tau_c) shows the markers a creep shows.
//
// The test, in contact, on the frames recorded since the contact began: three
// fields m frames apart, A = u_{k-2m}, B = u_{k-m}, C = u_k (m from 2 up in
// steps of a quarter, the longest first), d1 = B - A, d2 = C - B over the
// markers valid throughout, sigma the measured marker noise of the noisiest
// axis (pose/sensor_self_model.hpp: largest_axis_noise_mm; through a stereo
// pair the depth, six times the lateral noise, and a press moves the markers
// along it):
//   rho = (<d1, d2> + 3 n sigma^2) / (<d1, d1> - 6 n sigma^2)  (least squares
//   without the noise's own share: B's noise enters d1 and d2 with opposite
//   signs), a^m under a held press; rho has sd s / |d1|,
//   s = sigma sqrt(1 + (1 + rho)^2 + rho^2);
//   every frame j of the window on the exponential through A and B,
//   u_j = (1 - w_j) A + w_j B, w_j = (1 - q^(j - k + 2m)) / (1 - rho),
//   q = rho^(1/m), residual sd sigma sqrt(1 + (1 - w_j)^2 + w_j^2).
// A window is a creeping hold when rho is within (0, 1) by more than
// fit_sigmas of its sd (the increments keep their direction and shrink: one
// decaying process, not a finger at constant speed, not noise), every frame's
// largest residual is within the bound the largest of that many noise
// residuals passes with probability false_alarm (gel_recovery.hpp's
// noiseMaximum), and, following the exponential back from A frame by frame
// while each frame stays within one frame's bound, the frame where it breaks
// is off it by more than stop_factor x fit_sigmas (as gel_recovery.hpp's
// release asks of the frame a finger left in): the finger stopped there, at h.
// Then tau_c = (t_k - t_{k-m}) / -ln(rho), and c is the gain for which the
// causal inversion (creep_model.hpp) of every recorded frame since the
// contact began holds the elastic field still from h to k: golden section
// over r = c / (1 + c) in (0, 1) of the inverted fields' spread about their
// mean, measured in the markers' units (the inverted field is (u_k - a
// v_{k-1}) / (1 + (1 - a) c), so its spread is multiplied back by 1 + (1 - a) c;
// without that an unbounded gain stills any field by shrinking it). The model
// is taken when the spread's largest marker is within the same noise bound.
// From then on every frame's markers lose v (in and out of contact, as the
// gel keeps it); the contact analysis and the pose see u_e, the finger's own
// field, and a recovery after lift-off is v decaying (gel_recovery.hpp then
// finds nothing left to release).
// A recovery measures the gel too. Once the tracker has ended a contact, the
// field left behind is the delayed part alone, u_k = a u_{k-1} (creep_model.hpp
// with u_e = 0): the recorded contact goes on being recorded while each new
// frame is a scaled copy of the last (decayPair of gel_recovery.hpp: shrinking
// beyond fit_sigmas of its sd, every residual within the noise maximum) and
// holds a deformation (its largest marker beyond fit_sigmas of the noise of a
// marker against its rest, sigma sqrt 2: a field of noise alone also reads as
// a scaled copy, of about one half, as every frame shares the rest's noise).
// When the decay ends (a touch, or the field within the noise) and it lasted at
// least two frame pairs, a is the pooled least-squares scale of its pairs and
// tau_c = mean dt / -ln a; the gain is then the one whose causal inversion of
// the whole record, from v = 0 where the contact began, leaves no elastic
// field in the recovery's frames (golden section over r = c / (1 + c) in
// (0, max_relaxation): a gain without bound explains any recovery by a gel
// that follows every field at once, which a silicone that keeps at least
// 1 - max_relaxation of its modulus does not). The model is taken when the
// recovery's largest inverted marker is within the noise bound of all its
// frames and the gain is inside its range; a marker's sd there is the noise's
// and model_error of its displacement (one time constant for a gel that may
// have more, markers measured through the images: rendered recoveries miss a
// bound of the noise alone by 1.1-1.6 times with their constants within 5 %).
// A contact that began on a
// recovering gel (a remainder taken away) is not used: its record does not
// start from v = 0.
// The same measurement is made while the contact still holds, on the frames
// since the finger's field left that gel_recovery.hpp finds decaying as a
// gel does (GelRecovery::decayingFrames: each a shrinking copy of the first).
// A slow gel at a high frame rate shrinks too little in one frame for the
// release rule to end the contact (a finger that stayed would not yet show),
// but the whole record explains those frames only if no finger is left in
// them: a finger still holding a field stays in the inverted field. Tried
// when those frames number 1, 2, 4, 8, ..., so a long decay costs log2 of its
// frames in fits; the frame that measures the gel is analysed again without
// v (input/pose_tracker.hpp), and its contact ends there when only the gel
// held it.
// All bounds are multiples of the measured noise or noise probabilities; the
// gel's constants are what the markers show. Before a held press or a
// recovery has measured them nothing is taken away: the creep of the contacts
// up to then is read as depth, and their lift-offs are found by
// gel_recovery.hpp alone. The recorded frames are bounded by history_frames
// (memory, not a physical scale): a contact longer than that is not measured.
#pragma once

#include <cstdint>
#include <vector>

#include "core/marker_field.hpp"
#include "input/creep_model.hpp"

namespace onetip::input {

struct GelCreepOptions {
  bool enabled = true;
  double fit_sigmas = 8;       // [3, 100] noise sigmas: a scale within (0, 1) that noise does not make
  double false_alarm = 1e-3;   // [1e-9, 0.1] per window: chance that noise alone breaks a held window's fit
  double stop_factor = 3;      // [1, 100] x fit_sigmas: how far off the hold's exponential the frame before it is
  int history_frames = 1024;   // [16, 100000] frames of one contact (and its recovery) kept for the gain's fit
  double max_relaxation = 0.6;  // [0.05, 0.95] the largest relaxed fraction r of the modulus a recovery's fit
                                // considers (soft silicones relax 10-40 %)
  double model_error = 0.05;   // [0, 0.5] share of a marker's displacement a recovery's fit may leave unexplained
                               // besides the noise (a gel with more than one time constant, markers measured
                               // through the images)
  void validate() const;       // throws InputError naming the bad field
};

// One window of three fields under the test above (exposed for tests and tools). Each step is taken only when
// the one before passed: the frames' residuals when shrinking, the frames before A when exponential.
struct CreepWindow {
  bool measured = false;     // enough markers and an increment to scale
  double rho = 0;            // least-squares scale of the first increment onto the second
  double rho_sd = 0;         // its standard deviation
  bool shrinking = false;    // rho within (0, 1) by more than fit_sigmas of its sd
  double worst_sigmas = 0;   // the largest residual of a frame after A off the exponential, in units of its sd
                             // (from C backwards, up to the first beyond the window's noise bound)
  bool exponential = false;  // shrinking, and every frame after A within the window's noise bound
  int markers = 0;           // markers in the fit
  size_t start = 0;          // the earliest frame from which every frame up to A is on the same exponential
  double before_sigmas = 0;  // the frame before `start` off it, in units of its sd (0 when start is 0)
};

// The window of fields u[first .. first + 2m] (u_j = p_j - rest, S, mm), over the markers `valid`.
CreepWindow creepWindow(const std::vector<std::vector<Eigen::Vector3d>>& u, size_t first, size_t m,
                        const std::vector<std::uint8_t>& valid, double noise_mm, double fit_sigmas,
                        double false_alarm);

class GelCreep {
 public:
  explicit GelCreep(GelCreepOptions options = {});
  // The gel's delayed part v (S, mm per marker) for this frame, advanced with its raw field now - rest; empty
  // until the gel's creep has been measured. Call once per frame, before the contact analysis.
  const std::vector<Eigen::Vector3d>& advance(const MarkerField& now, const MarkerField& rest, double t);
  // After the frame's analysis, while not yet measured: `now` as the analysis saw it (a recovery's remainder
  // taken away), in_contact the tracker's decision, noise_mm the measured marker noise, remainder the
  // recovery's remainder (S, mm; empty when none). True when this frame measured the gel (a held press or a
  // recovery): v then holds the gel's delayed part as of this frame, and the recovery's remainder is to be
  // dropped.
  // decaying_frames: in contact, the frames since the finger's field left that decayed as a gel does
  // (GelRecovery::decayingFrames); the gel is measured from them as from a recovery.
  bool observe(const MarkerField& now, const MarkerField& rest, double t, bool in_contact, double noise_mm,
               const std::vector<Eigen::Vector3d>& remainder, int decaying_frames = 0);
  const CreepModel& model() const { return model_; }
  const std::vector<Eigen::Vector3d>& delayed() const { return delayed_; }
  void reset();

 private:
  bool identify(double noise_mm);
  // Frames recorded after the contact ended, while they decay (the recovery above); true when measured.
  bool observeRecovery(std::vector<Eigen::Vector3d> u, const std::vector<std::uint8_t>& valid, double t,
                       double noise_mm);
  // The recovery recorded from history_[recovery_start_] to the last frame: measures the gel from it when it is
  // long enough, then clears the record. True when measured.
  bool finishRecovery(double noise_mm);
  bool identifyFromRecovery(size_t start, double noise_mm);
  void clearHistory();

  GelCreepOptions options_;
  CreepModel model_;
  std::vector<Eigen::Vector3d> delayed_;  // v, when measured
  double last_t_ = 0;
  bool have_t_ = false;
  std::vector<std::vector<Eigen::Vector3d>> history_;  // u since the contact began (before measured)
  std::vector<std::uint8_t> history_valid_;           // markers valid in every recorded frame
  std::vector<double> history_t_;
  bool history_had_remainder_ = false;  // the recorded contact began on a recovering gel
  static constexpr size_t kNoRecovery = static_cast<size_t>(-1);
  size_t recovery_start_ = kNoRecovery;  // the first frame of the record after the contact ended
};

}  // namespace onetip::input
