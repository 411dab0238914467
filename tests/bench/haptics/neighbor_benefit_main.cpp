// haptic_neighbor_benefit: where retrieving more neighbours (Eq. 7) helps the
// BioTac-like model and where it hurts, as a function of how far the remote
// contacts lie from what the display can reproduce, and whether sensor noise
// or the servos' dynamics change that.
//
// The side interactions (back-, tip-, left-, right-flat-X and complex) start
// and end with the plate rolled `side_tilt_deg` onto the side of the finger
// (remote_interactions.hpp). A 1-DoF display only presses flat, so the larger
// the tilt, the farther those sensations are from its reachable set S_*. Far
// from S_*, the n nearest rows are almost equally distant, Eq. 7 weights them
// almost uniformly, and the mean command drifts away from the nearest row
// toward the densely sampled shallow presses. This program runs the full
// 27-condition evaluation (objective_evaluation.hpp) for
//   - each tilt 0, 10, 20, 30, 40 deg with the docs' model (2 counts of noise,
//     the device following each command at once), and
//   - at the default 30 deg: 10 and 30 counts of noise (all three sensors), and
//     the paper's servos (servo_response.hpp: 50 Hz, 0.5 deg, 857 deg/s),
// and writes, per run and DoF, the mean Eq. 9 error over steps and
// interactions for n = 1, 4, 8:
//   <out_dir>/neighbor_benefit.csv
//     (side_tilt_deg,noise_counts,servo_dynamics,dof,neighbors,mean_normalized_error)
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
  struct Run {
    double tilt_deg, noise_counts;
    bool servo_dynamics;
  };
  const Run runs[] = {{0.0, 2.0, false},  {10.0, 2.0, false}, {20.0, 2.0, false}, {30.0, 2.0, false},
                      {40.0, 2.0, false}, {30.0, 10.0, false}, {30.0, 30.0, false}, {30.0, 2.0, true}};
  const PlatformKinematics device;
  CsvWriter out(std::string(argv[1]) + "/neighbor_benefit.csv",
                {"side_tilt_deg", "noise_counts", "servo_dynamics", "dof", "neighbors", "mean_normalized_error"});
  for (const Run& run : runs) {
    BiotacLikeOptions o;
    o.noise_counts = run.noise_counts;
    const BiotacLikeEvaluationSensors sensors(o);
    const TactileDataset full = simulateDataset(device, sensors.collection, 3.0);
    ObjectiveEvaluationOptions options;
    options.interactions.side_tilt_deg = run.tilt_deg;
    if (run.servo_dynamics) options.servo = ServoResponseOptions{};
    std::map<std::pair<int, int>, std::pair<double, int>> by_dof_n;  // (dof, n) -> (sum, count)
    for (const EvaluationRow& row : runObjectiveEvaluation(full, sensors.remote, sensors.in_device, device, options)) {
      auto& [sum, count] = by_dof_n[{static_cast<int>(row.condition.dof), row.condition.neighbors}];
      sum += row.normalized_error;
      ++count;
    }
    for (const auto& [key, acc] : by_dof_n) {
      const double mean = acc.first / acc.second;
      out.row({formatNumber(run.tilt_deg), formatNumber(run.noise_counts), run.servo_dynamics ? "1" : "0",
               std::to_string(key.first), std::to_string(key.second), formatNumber(mean, 4)});
      std::printf("tilt %2.0f deg  noise %2.0f  servos %d  dof %d  n %d: e_f %.4f\n", run.tilt_deg, run.noise_counts,
                  run.servo_dynamics ? 1 : 0, key.first, key.second, mean);
    }
  }
  out.commit();
  return 0;
}
