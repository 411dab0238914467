// haptic_neighbor_benefit: where retrieving more neighbours (Eq. 7) helps the
// BioTac-like model and where it hurts, as a function of how far the remote
// contacts lie from what the display can reproduce.
//
// The side interactions (back-, tip-, left-, right-flat-X and complex) start
// and end with the plate rolled `side_tilt_deg` onto the side of the finger
// (remote_interactions.hpp). A 1-DoF display only presses flat, so the larger
// the tilt, the farther those sensations are from its reachable set S_*. Far
// from S_*, the n nearest rows are almost equally distant, Eq. 7 weights them
// almost uniformly, and the mean command drifts away from the nearest row
// toward the densely sampled shallow presses. This program runs the full
// 27-condition evaluation (objective_evaluation.hpp, 2 counts of noise as in
// docs/haptics) for each tilt and writes, per tilt and DoF, the mean Eq. 9
// error over steps and interactions for n = 1, 4, 8:
//   <out_dir>/neighbor_benefit.csv  (side_tilt_deg,dof,neighbors,mean_normalized_error)
// docs/haptics/make_charts.py draws neighbor_benefit.png from it.
// usage: haptic_neighbor_benefit OUT_DIR
#include <cstdio>
#include <iostream>
#include <map>
#include <utility>

#include "core/csv_table.hpp"
#include "haptics/biotac_like_sensor.hpp"
#include "haptics/display_grid.hpp"
#include "haptics/objective_evaluation.hpp"

using namespace onetip;
using namespace onetip::haptics;

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: haptic_neighbor_benefit OUT_DIR\n";
    return 2;
  }
  const PlatformKinematics device;
  BiotacLikeOptions o;
  o.noise_counts = 2.0;
  const BiotacLikeEvaluationSensors sensors(o);
  const TactileDataset full = simulateDataset(device, sensors.collection, 3.0);

  CsvWriter out(std::string(argv[1]) + "/neighbor_benefit.csv",
                {"side_tilt_deg", "dof", "neighbors", "mean_normalized_error"});
  for (double tilt : {0.0, 10.0, 20.0, 30.0, 40.0}) {
    ObjectiveEvaluationOptions options;
    options.interactions.side_tilt_deg = tilt;
    std::map<std::pair<int, int>, std::pair<double, int>> by_dof_n;  // (dof, n) -> (sum, count)
    for (const EvaluationRow& row : runObjectiveEvaluation(full, sensors.remote, sensors.in_device, device, options)) {
      auto& [sum, count] = by_dof_n[{static_cast<int>(row.condition.dof), row.condition.neighbors}];
      sum += row.normalized_error;
      ++count;
    }
    for (const auto& [key, acc] : by_dof_n) {
      const double mean = acc.first / acc.second;
      out.row({formatNumber(tilt), std::to_string(key.first), std::to_string(key.second), formatNumber(mean, 4)});
      std::printf("tilt %2.0f deg  dof %d  n %d: e_f %.4f\n", tilt, key.first, key.second, mean);
    }
  }
  out.commit();
  return 0;
}
