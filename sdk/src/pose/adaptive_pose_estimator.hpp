// pose/adaptive_pose_estimator.hpp — the finger's motion from the contact
// markers, choosing the cheapest model the contact state supports.
//
// Per frame k in contact (S, mm; rotations in radians), with every threshold
// derived from what the sensor measures about itself (noise, pitch, frame
// interval; pose/adaptive_pose_options.hpp):
//  1. Stick/slip labels (contact/stick_slip_classifier.hpp) against the trial
//     motion dT0 = Kabsch(T_{k-1} a_i -> p_i) over the sticking markers,
//     whose references are their anchors a_i carried by the previous pose
//     estimate T_{k-1} (so measurement noise does not accumulate frame to
//     frame), trimmed and robust (pose/anchored_fit.hpp, which also says
//     what a thin stick set can fix). On a developed contact (at least
//     min_macro_markers region markers) only the labelled markers the finger
//     can be touching enter the fits (pose/touching_markers.hpp: not where the
//     pad relaxes convexly around the dimple), unless fewer than
//     min_thin_stick_markers are left; and when none of those sticks while at
//     least min_thin_stick_markers of them are labelled detached (pushed along
//     the normal further than the estimate carries them), those stick again
//     at T_{k-1} (detachedUnderTheFinger). On a smaller contact, when the
//     trim drops most labelled markers of the dimple's cap (capMarkers), the
//     fit is redone over those alone (fitAnchoredOnTheCap: the skin beside
//     a touch lags it and outnumbers it as a press begins). The kept markers
//     are the stick set.
//  2. The increment dT_k = T_k T_{k-1}^-1 from the model pose/model_selection.hpp picks:
//       full stick (no slipping marker)      -> Kabsch / Umeyama (rigid_fit.hpp, Eq. 1);
//       partial slip (Eq. 16 holds)          -> Ceres stick/slip least squares (Eq. 13-15);
//       Eq. 16 fails (macroscopic slip), or on a developed contact a thin
//       stick set creeps (slip markers overtake it: stick_set_creep.hpp)
//                                            -> motion of the footprint centroid
//         (for a contact smaller than min_macro_markers, whose footprint is
//         too coarse, the mean motion of its markers instead; but while the
//         finger visibly turns, i.e. the markers' rigid motion tilts it beyond
//         macro_tilt_gate_deg over the window, and they span an area, that
//         rigid motion: a translation would freeze the tilt at the reversal).
//     Every model yields an increment and T_k = dT_k T_{k-1}, so a hand-over
//     between models never makes the output jump.
//  3. Macroscopic slip is entered when Eq. 16 fails on a developed contact
//     (at least min_macro_markers region markers) and is held (hysteresis)
//     for at least a window. The way back, from macroscopic slip and from
//     any frame where Eq. 16 fails: over the last window a rigid consensus of
//     at least restick_fraction of the contact's markers (and no fewer than
//     min_thin_stick_markers, spanning an area) carries the footprint
//     (stickingAgain below). The consensus sticks, the others slip, and this
//     frame's increment is the consensus's own motion since the last frame
//     (no catch-up over the window). Labels are not the test: judged against
//     an estimate that stalled, markers that stick again (at a reversal the
//     whole contact does) never look quiet. Sliding markers that creep slower
//     than the slip threshold move as one body too, but leave the footprint
//     behind, so they cannot pull the estimate back to a stick model that
//     would stall. A slow slide whose markers never
//     cross the threshold is caught from the footprint: while the finger
//     sticks, the pressure footprint is carried by the finger. Over the last
//     window the measured footprint centre is compared with
//     where the estimated finger motion would have carried it; a drift above
//     the drift floor and above macro_drift_ratio of the footprint's own travel
//     means the finger slides while the markers stay behind (in partial slip
//     the footprint leads the finger by ~20% of the travel in the simulator,
//     at gross slip the stalled estimate loses all of it), in
//     consecutive frames over macro_confirm_s (a footprint jittering because
//     markers are lost is not a slide). T_k then catches
//     up by the drift once and the centroid model takes over. No decision is
//     taken while the region size changes by macro_size_change or the finger
//     tilts by macro_tilt_gate_deg within the window (rolling and pitching
//     move the footprint over the finger legitimately), and no drift is
//     reported while the normal deformation under the footprint deepens by
//     macro_size_change (a deepening press moves its centre).
//  4. Safety: one frame's increment is limited to max_speed_mm_s of motion of
//     the contact point and max_rate_deg_s of rotation times the frame
//     interval (scaled down, direction kept; pose/step_limit.hpp).
// With ModelPolicy::weighted every frame goes to the one-objective prototype
// instead (pose/weighted_pose_estimator.hpp, a comparison policy).
#pragma once

#include <Eigen/Geometry>
#include <deque>
#include <optional>

#include "contact/contact_field.hpp"
#include "contact/stick_slip_classifier.hpp"
#include "core/marker_field.hpp"
#include "onetip/types.hpp"
#include "pose/adaptive_pose_options.hpp"
#include "pose/contact_snapshot.hpp"
#include "pose/model_selection.hpp"
#include "pose/pose_step.hpp"
#include "pose/weighted_pose_estimator.hpp"

namespace onetip::pose {

class AdaptivePoseEstimator {
 public:
  explicit AdaptivePoseEstimator(AdaptivePoseOptions options = {});
  void reset();
  // `field` from ContactAnalyzer::analyze(now_S, rest_S); `self` what the
  // sensor has measured about itself so far (noise, pitch, frame interval).
  // Markers of now_S graded below field.min_confidence are treated as not
  // measured (contact::trustedMarkers).
  PoseStep update(const contact::ContactField& field, const MarkerField& now_S, const SensorSelf& self);
  const contact::StickSlipClassifier& classifier() const { return classifier_; }
  const AdaptivePoseOptions& options() const { return options_; }

 private:
  // The region holding most of the contact's labelled markers, or -1 when
  // none holds any: the finger tracked has lifted (another keeps the pad in
  // contact) and its contact has ended.
  int trackedRegion(const contact::ContactField& field) const;
  PoseStep start(const contact::ContactField& field, const MarkerField& now);
  Eigen::Isometry3d solveIncrement(const contact::ContactField& field, const MarkerField& now, PoseStep& step);
  struct Drift {
    Eigen::Vector3d drift{0, 0, 0};  // footprint off the finger over the window (S.x, S.y; mm)
    bool turning = false;            // the finger tilted beyond the gate over the window (a full window)
    bool decided = false;            // the finger neither turned nor the region resized beyond the gates
    bool exceeds = false;            // decided, and beyond the tolerance
  };
  Drift footprintDrift(const contact::ContactField& field, const MarkerField& now,
                       const contact::ContactRegion& region, const Eigen::Isometry3d& next_pose) const;
  void checkMacroSlip(const contact::ContactField& field, const MarkerField& now, const contact::ContactRegion& region,
                      Eigen::Isometry3d& increment);
  void enterMacroSlip(const MarkerField& now, const Eigen::Isometry3d& increment);
  // Sticking markers carry the finger again: over the last window (frame k-w
  // to k) the markers that moved as one rigid body W (fitConsensus,
  // anchored_fit.hpp, trimmed at twice the slip threshold: a marker that
  // sticks in both frames is within one of the finger's motion in each; the
  // marker layer under the skin does not follow a turning finger rigidly, and
  // at one threshold a tilt reversal that sticks again kept the footprint
  // model for 20-30 frames), at least restick_fraction of the contact's measured
  // markers and min_thin_stick_markers, spanning an area that fixes a general
  // rotation, carry the footprint:
  // min over s in [0, 1] of |c_k - W c_{k-w} - s rho| < exit lag +
  // macro_drift_ratio |rho| (x-y), rho the rolling shift (contact_cap.hpp) of
  // the part of W's turn beyond slip threshold / the consensus's smaller x-y
  // extent (a turn the trim could let a non-rigid set fake is not credited: a
  // slide's saturated markers drift that much): the footprint moved the way
  // the turn rolls it, by no more than rolling a cap of the dimple's
  // curvature would. rho is read from the dimple, not the finger, so it is
  // only approximate: at a rolling reversal 0.07-0.12 mm of lag can remain
  // beside a rho of 0.29-0.35 mm (hence the tolerance grows with rho), and
  // under a flat plate (its cap's radius clipped at 1 m) a 0.27 deg turn
  // predicts 4.0 mm where the footprint moves 1.1 mm the same way (hence a
  // shift short of rho counts). The consensus is left in `sticking`.
  bool stickingAgain(const contact::ContactField& field, const std::vector<int>& members, const MarkerField& now,
                     std::vector<int>& sticking) const;
  // When stickingAgain holds: the consensus labelled stick, every other marker
  // slip, and the increment the consensus's own motion since the last frame
  // (none over the window: a window straddling a reversal holds slide as well
  // as stick). nullopt (labels untouched) when it does not hold.
  std::optional<Eigen::Isometry3d> restick(const contact::ContactField& field, const std::vector<int>& members,
                                           const MarkerField& now);
  // The valid members' smaller principal x-y extent reaches the min spread (they fix a general rotation).
  bool spansArea(const std::vector<int>& members, const MarkerField& now) const;
  Eigen::Isometry3d centroidStep(const contact::ContactField& field, const std::vector<int>& members,
                                 const MarkerField& now) const;
  void remember(const contact::ContactField& field, const MarkerField& now, const contact::ContactRegion& region);
  // Per-marker stick probabilities and the pose's sd for this frame (pose/pose_uncertainty.hpp): the
  // stick set is the stick-labelled markers weighted by their probability; none while the footprint
  // carries the estimate.
  void reportUncertainty(const MarkerField& now, const Eigen::Isometry3d& increment, PoseStep& step);

  AdaptivePoseOptions options_;
  WeightedPoseEstimator weighted_;
  EstimatorThresholds t_;                    // of the frame being processed
  contact::StickSlipClassifier classifier_;
  PoseUncertainty uncertainty_;
  bool active_ = false;
  bool macro_slip_ = false;
  int macro_frames_ = 0;                     // frames since macroscopic slip began
  int macro_suspect_frames_ = 0;             // consecutive frames with a footprint drift
  Eigen::Isometry3d pose_ = Eigen::Isometry3d::Identity();
  Eigen::Vector3d c0_{0, 0, 0};
  std::deque<ContactSnapshot> history_;      // newest last; history_.back() is frame k-1
};

}  // namespace onetip::pose
