// pose/pose_step.hpp — what the pose estimator reports for one frame: the
// finger's increment and pose since onset (S, mm; rotations as isometries),
// the per-marker labels and stick probabilities, and the sd of the 6-D input.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "contact/stick_slip_classifier.hpp"
#include "onetip/types.hpp"
#include "pose/adaptive_pose_options.hpp"
#include "pose/model_selection.hpp"

namespace onetip::pose {

struct PoseStep {
  bool active = false;         // in contact and tracking
  bool onset = false;          // first frame of a contact (pose = identity); with another
                               // finger on the pad it may follow the last frame of one directly
  bool step_limited = false;   // the increment was scaled down (safety limit)
  bool solver_failed = false;  // Ceres or Kabsch failed; the centroid model stood in
  bool stuck_again = false;    // the markers stick again (stickingAgain): a stick model took over from the footprint
  PoseModel model = PoseModel::none;
  ContactState state = ContactState::none;
  int region = -1;  // index into ContactField::regions that is tracked
  int n_stick = 0, n_slip = 0;
  Eigen::Isometry3d increment = Eigen::Isometry3d::Identity();  // T_k T_{k-1}^-1
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();       // T_k, since onset
  Eigen::Vector3d onset_centroid{0, 0, 0};                      // c0 (S, mm)
  EstimatorThresholds thresholds;                               // in force this frame
  std::vector<contact::MarkerLabel> labels;                     // per marker id: outside, stick or slip
  std::vector<double> stick_probability;  // per marker id, [0, 1] (contact/stick_probability.hpp); 0 outside
  Input6 sd;  // one standard deviation of each component of the 6-D input (mm, deg; pose/pose_uncertainty.hpp)
};

}  // namespace onetip::pose
