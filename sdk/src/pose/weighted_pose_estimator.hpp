// pose/weighted_pose_estimator.hpp — the finger's motion from one objective:
// contact markers registered against their anchors on the finger with stick
// weights the estimator finds itself, the footprint, and a motion prior.
//
// Per frame k in contact (S, mm; rotations in radians):
//  1. Every marker of the tracked region has an anchor a_i on the finger: the
//     point it touched when it last stuck (T^-1 p_i under the estimate T).
//  2. The increment dT = T_k T_{k-1}^-1 minimises the weighted problem of
//     pose/weighted_increment.hpp; the stick weights w_i come from graduated
//     non-convexity on the truncated least-squares cost
//     (pose/truncated_least_squares.hpp), whose bound is the chi-square
//     quantile of the marker noise the sensor measures at rest. Full stick,
//     partial slip and gross slip are what the weights reduce to: all ones
//     (Kabsch, Eq. 1), some (Eq. 13-15), none (the footprint and the normal
//     residuals; Sec. III-D).
//  3. The footprint is carried by the finger: over the last window the
//     footprint centre measured now is compared with where the increment
//     carries the one measured a window ago. Its sd is the footprint's own
//     model error: the drift floor, or a share of its travel (in partial slip
//     the footprint leads the finger by a share of its slide). So a stick set
//     that creeps behind a sliding finger loses to the footprint once its lag
//     outweighs the truncated price of letting every marker slip.
//  4. A marker whose weight ends below one half slips: it sticks again where it
//     now is (the brush model's re-anchoring) from the next frame on.
//  5. Safety: the increment is limited (pose/step_limit.hpp).
//  6. The reported sd (pose/pose_uncertainty.hpp) takes the weighted stick set
//     as the markers that fix the motion.
#pragma once

#include <deque>
#include <vector>

#include "contact/contact_field.hpp"
#include "core/marker_field.hpp"
#include "pose/adaptive_pose_options.hpp"
#include "pose/contact_snapshot.hpp"
#include "pose/pose_step.hpp"
#include "pose/pose_uncertainty.hpp"
#include "pose/weighted_increment.hpp"

namespace onetip::pose {

class WeightedPoseEstimator {
 public:
  explicit WeightedPoseEstimator(const AdaptivePoseOptions& options);
  void reset();
  // One frame in contact (the caller resets out of contact): `now` holds only the markers the contact
  // stage trusts; `thresholds` those the sensor's self-model gives this frame.
  PoseStep update(const contact::ContactField& field, const MarkerField& now, const EstimatorThresholds& thresholds);

 private:
  PoseStep start(const contact::ContactField& field, const MarkerField& now);
  int trackedRegion(const contact::ContactField& field) const;
  void anchor(int id, const Eigen::Vector3d& p);
  // This frame kept for the footprint window (the last window_frames frames, newest last).
  void remember(const contact::ContactField& field, const MarkerField& now, const contact::ContactRegion& region);
  std::optional<FootprintEvidence> footprint(const contact::ContactField& field, const std::vector<int>& members,
                                             const MarkerField& now) const;
  // The increment minimising truncatedCost; the markers' final weights are left in the problem.
  Eigen::Isometry3d solve(WeightedIncrementProblem& problem) const;
  void report(const MarkerField& now, const std::vector<int>& members, const Eigen::Isometry3d& increment,
              PoseStep& step);

  AdaptivePoseOptions options_;
  EstimatorThresholds t_;
  PoseUncertainty uncertainty_;
  bool active_ = false;
  Eigen::Isometry3d pose_ = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d last_increment_ = Eigen::Isometry3d::Identity();
  Eigen::Vector3d c0_{0, 0, 0};
  std::vector<Eigen::Vector3d> anchor_;       // per marker id (finger frame = S at onset, mm)
  std::vector<Eigen::Vector3d> anchored_at_;  // p_i when anchored (S, mm)
  std::vector<std::uint8_t> anchored_;
  std::vector<double> weight_;           // stick weight at the last frame
  std::vector<double> drift_mm_;         // |T a_i - p_i| at the last frame (mm)
  std::vector<double> drift_sd_;         // s_i at the last frame (mm): weighted_increment.hpp
  std::deque<ContactSnapshot> history_;  // newest last
};

}  // namespace onetip::pose
