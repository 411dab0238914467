// contact/stick_slip_classifier.hpp — per-marker stick/slip labels, frame by frame.
//
// Method (a discrete brush model run on the measurements): every contact-region
// marker i carries an anchor a_i, its position in the finger's frame,
// a_i = T^-1 p_i (T: the finger's estimated pose since onset, S, mm), taken when
// it enters the region or last slipped. A sticking marker stays on its anchor,
// so its drift d_i = p_i - T a_i only holds measurement noise. Classification
// with the current pose estimate T_k, splitting d_i along the contact normal
// n_i into a normal part d_n = d_i . n_i and a tangential part d_t:
//   |d_i| > slip_threshold_mm -> the marker does not follow the
//     finger: `slip` when the tangential part dominates (it slides over the
//     finger), `detached` when the normal part does (a region marker that is
//     not actually touching, e.g. just outside the contact edge); a_i is
//     re-anchored at T_k^-1 p_i;
//   a slipping or detached marker whose drift stays below the threshold for
//   stick_hold_frames consecutive frames sticks again (hysteresis).
// Because the drift is measured against a fixed anchor, slow creep accumulates
// until it crosses the threshold while position noise does not. The pose T_k
// comes from a fit over the sticking markers trimmed of those drifting beyond
// the same threshold (pose/rigid_fit.hpp), so undetected slip does not bend
// T_k and push true stick markers over the threshold.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "core/marker_field.hpp"

namespace onetip::contact {

enum class MarkerLabel : std::uint8_t { outside = 0, stick = 1, slip = 2, detached = 3 };

struct StickSlipOptions {
  double slip_threshold_mm = 0.01;  // drift from the anchor (about 7 sigma of the drift noise)
  int stick_hold_frames = 10;       // quiet frames before a slipping marker sticks again
  void validate() const;            // throws InputError naming the bad field
};

class StickSlipClassifier {
 public:
  explicit StickSlipClassifier(StickSlipOptions options = {});

  // New thresholds from the next classify() on (validated like the options).
  void setOptions(const StickSlipOptions& options);
  // Forgets every marker; sizes the tables for `marker_count` markers.
  void reset(int marker_count);
  // Markers of `members` that are valid in `now` keep their state; every other
  // marker gets the label outside. One that was merely not measured this frame
  // (invalid in `now`) is remembered: anchorNew gives it back its label and
  // anchor when it is seen again, so a marker lost for a frame during slip does
  // not return as a fresh, trusted stick marker. One measured outside the
  // region is forgotten.
  void retain(const std::vector<int>& members, const MarkerField& now);
  // Anchors the valid members that have no anchor yet at pose^-1 p (label stick);
  // a remembered marker (see retain) takes back its label and anchor instead.
  void anchorNew(const std::vector<int>& members, const MarkerField& now, const Eigen::Isometry3d& pose);
  // Labels every anchored marker from its drift under `pose`; returns how many
  // markers changed label.
  int classify(const MarkerField& now, const std::vector<Eigen::Vector3d>& normals, const Eigen::Isometry3d& pose);
  // Macroscopic slip: every anchored marker slips and is re-anchored under `pose`.
  void markAllSlipping(const MarkerField& now, const Eigen::Isometry3d& pose);
  // Every anchored marker sticks, re-anchored under `pose`.
  void markAllSticking(const MarkerField& now, const Eigen::Isometry3d& pose);
  // The markers `ids` (anchored ones) stick, re-anchored at pose^-1 p with p their
  // positions in `at` (measured there); every other label is kept.
  void reattach(const std::vector<int>& ids, const MarkerField& at, const Eigen::Isometry3d& pose);
  // Every anchored marker is re-anchored under `pose`: those in `sticking` stick, the others slip.
  void markSticking(const std::vector<int>& sticking, const MarkerField& now, const Eigen::Isometry3d& pose);

  MarkerLabel label(int id) const { return label_[static_cast<size_t>(id)]; }
  const Eigen::Vector3d& anchor(int id) const { return anchor_[static_cast<size_t>(id)]; }
  const std::vector<MarkerLabel>& labels() const { return label_; }
  std::vector<int> withLabel(MarkerLabel l) const;
  // Classifications since the marker joined the contact (anchorNew gave it a
  // fresh anchor); a remembered marker (see retain) keeps its count.
  int framesInContact(int id) const { return frames_in_contact_[static_cast<size_t>(id)]; }
  // The marker's drift off its anchor when last judged or re-anchored (mm): the evidence of
  // contact/stick_probability.hpp; 0 for a marker anchored afresh.
  double lastDrift(int id) const { return drift_[static_cast<size_t>(id)]; }

 private:
  void reanchor(int id, const MarkerField& now, const Eigen::Isometry3d& pose_inverse);

  StickSlipOptions options_;
  std::vector<MarkerLabel> label_;
  std::vector<MarkerLabel> unseen_label_;  // label when last measured, for a member not measured since
  std::vector<Eigen::Vector3d> anchor_;
  std::vector<int> quiet_frames_;
  std::vector<int> frames_in_contact_;
  std::vector<double> drift_;
};

}  // namespace onetip::contact
