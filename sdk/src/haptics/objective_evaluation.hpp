// haptics/objective_evaluation.hpp — the journal paper's objective
// evaluation (Sec. 3.1, Eq. 9, Fig. 7), reproduced in simulation.
//
// For every condition (step theta in {3, 6, 9} deg x neighbours n in {1, 4, 8}
// x device DoF in {1, 2, 3}) the renderer is built on the subset of the one
// 3-deg dataset (dof_reduction.hpp). Each remote interaction's recording s(k)
// (the sensor touched by the moving plate) is rendered to m(k), the simulated
// device is driven to m(k) with the sensor inside it, and what it feels there
// is s_r(k). Errors over the K samples and the N' non-constant channels:
//   Eq. 9:   e_f = 1/K sum_k ( sum_i |s_i - s_r,i| / sigma_i ) / N'
//   % full:  p_f = 100/K sum_k ( sum_i |s_i - s_r,i| / fullScale_i ) / N'
// sigma_i: the standard deviation of channel i over the full 3-deg dataset
// (the scaling the renderer applies, so the metric is the same for every
// condition); fullScale_i from the sensor model (4095 counts for BioTac-like),
// or, when the model declares none (onetip's displacements), channel i's
// range (max - min) over the full dataset. Remote plates are placed against
// the remote sensor's FingertipShape. By default the device is where m(k) puts
// it at once; with `servo` set, m(k) streams through the servos' response
// (servo_response.hpp, starting at rest for each replay) and s_r(k) is felt
// 1 / rate_hz after m(k) was sent.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "haptics/dof_reduction.hpp"
#include "haptics/remote_interactions.hpp"
#include "haptics/servo_response.hpp"
#include "haptics/tactile_dataset.hpp"
#include "haptics/tactile_sensor_model.hpp"

namespace onetip::haptics {

struct EvaluationCondition {
  double step_deg = 3.0;
  int neighbors = 1;
  DeviceDof dof = DeviceDof::three;
};

struct EvaluationRow {
  RemoteInteraction interaction = RemoteInteraction::flat;
  EvaluationCondition condition;
  size_t dataset_rows = 0;         // |S_*| of the condition
  double normalized_error = 0.0;   // Eq. 9
  double percent_full_scale = 0.0;
};

struct ObjectiveEvaluationOptions {
  std::vector<double> steps_deg = {3.0, 6.0, 9.0};
  std::vector<int> neighbors = {1, 4, 8};
  std::vector<int> dofs = {1, 2, 3};
  InteractionOptions interactions;
  std::optional<ServoResponseOptions> servo;  // unset: the device follows m(k) instantly
  void validate() const;  // throws InputError naming the bad field
};

// full: the dataset on the 3-deg grid (3-DoF). remote: the sensor in the
// remote environment; in_device: the sensor inside the display (usually the
// same model). Rows are ordered interaction-major, then step, n, DoF.
// `progress` (optional) is called after each condition with (done, total).
std::vector<EvaluationRow> runObjectiveEvaluation(const TactileDataset& full, const TactileSensorModel& remote,
                                                  const TactileSensorModel& in_device,
                                                  const PlatformKinematics& device,
                                                  const ObjectiveEvaluationOptions& options = {},
                                                  const std::function<void(int, int)>& progress = {});

// Mean over interactions of each condition (the points of Fig. 7).
struct ConditionSummary {
  EvaluationCondition condition;
  double mean_normalized_error = 0.0;
  double sem_normalized_error = 0.0;  // standard error of the mean over interactions
  double mean_percent_full_scale = 0.0;
};
std::vector<ConditionSummary> summarizeByCondition(const std::vector<EvaluationRow>& rows);

}  // namespace onetip::haptics
