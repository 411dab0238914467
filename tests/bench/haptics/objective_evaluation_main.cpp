// haptic_objective_evaluation: the journal paper's 27-condition objective
// evaluation in simulation (haptics/objective_evaluation.hpp), written as
//   <out_dir>/objective_<sensor>_evaluation.csv  (interaction,step_deg,neighbors,dof,
//                                        dataset_rows,normalized_error,percent_full_scale)
//   <out_dir>/objective_<sensor>_summary.csv     (step_deg,neighbors,dof,mean_normalized_error,
//                                        sem_normalized_error,mean_percent_full_scale)
// docs/haptics/make_charts.py draws Fig. 7-like charts from them.
// Sensors: biotac (the 20-channel BioTac-like model, noise_counts of noise,
// default 2; interactions at 100 Hz, 3 repetitions) or onetip (the pad's 5 x 5
// marker-displacement grid, noise-free; interactions at 25 Hz, 1 repetition,
// since each reading is a contact solve of ~1-2 ms).
// usage: haptic_objective_evaluation OUT_DIR [biotac|onetip] [noise_counts]
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>

#include "core/csv_table.hpp"
#include "haptics/biotac_like_sensor.hpp"
#include "haptics/display_grid.hpp"
#include "haptics/objective_evaluation.hpp"
#include "haptics/onetip_contact_sensor.hpp"

using namespace onetip;
using namespace onetip::haptics;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: haptic_objective_evaluation OUT_DIR [biotac|onetip] [noise_counts]\n";
    return 2;
  }
  const std::string dir = argv[1];
  const std::string sensor_name = argc > 2 ? argv[2] : "biotac";
  const PlatformKinematics device;
  ObjectiveEvaluationOptions options;
  std::unique_ptr<BiotacLikeEvaluationSensors> biotac;
  std::unique_ptr<OnetipContactSensor> onetip_sensor;  // deterministic: serves all three roles
  const TactileSensorModel *collection = nullptr, *remote = nullptr, *in_device = nullptr;
  if (sensor_name == "biotac") {
    BiotacLikeOptions o;
    o.noise_counts = argc > 3 ? std::stod(argv[3]) : 2.0;
    biotac = std::make_unique<BiotacLikeEvaluationSensors>(o);
    collection = &biotac->collection;
    remote = &biotac->remote;
    in_device = &biotac->in_device;
  } else if (sensor_name == "onetip") {
    onetip_sensor = std::make_unique<OnetipContactSensor>();
    collection = remote = in_device = onetip_sensor.get();
    options.interactions.rate_hz = 25.0;
    options.interactions.repetitions = 1;
  } else {
    std::cerr << "haptic_objective_evaluation: sensor '" << sensor_name << "' is not biotac or onetip\n";
    return 2;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const TactileDataset full = simulateDataset(device, *collection, 3.0);
  const auto t1 = std::chrono::steady_clock::now();
  const auto rows = runObjectiveEvaluation(full, *remote, *in_device, device, options, [](int done, int total) {
    std::fprintf(stderr, "\rcondition %d/%d", done, total);
  });
  const auto t2 = std::chrono::steady_clock::now();
  std::fprintf(stderr, "\ndataset %.1f s, evaluation %.1f s\n", std::chrono::duration<double>(t1 - t0).count(),
               std::chrono::duration<double>(t2 - t1).count());

  CsvWriter detail(dir + "/objective_" + sensor_name + "_evaluation.csv", {"interaction", "step_deg", "neighbors", "dof", "dataset_rows",
                                                       "normalized_error", "percent_full_scale"});
  for (const auto& r : rows)
    detail.row({std::string(toString(r.interaction)), formatNumber(r.condition.step_deg),
                std::to_string(r.condition.neighbors), std::to_string(static_cast<int>(r.condition.dof)),
                std::to_string(r.dataset_rows), formatNumber(r.normalized_error, 4),
                formatNumber(r.percent_full_scale, 4)});
  detail.commit();
  CsvWriter summary(dir + "/objective_" + sensor_name + "_summary.csv", {"step_deg", "neighbors", "dof", "mean_normalized_error",
                                                     "sem_normalized_error", "mean_percent_full_scale"});
  for (const auto& s : summarizeByCondition(rows)) {
    summary.row({formatNumber(s.condition.step_deg), std::to_string(s.condition.neighbors),
                 std::to_string(static_cast<int>(s.condition.dof)), formatNumber(s.mean_normalized_error, 4),
                 formatNumber(s.sem_normalized_error, 4), formatNumber(s.mean_percent_full_scale, 4)});
    std::printf("step %g n %d dof %d: e_f %.3f +- %.3f  (%.2f%% of full scale)\n", s.condition.step_deg,
                s.condition.neighbors, static_cast<int>(s.condition.dof), s.mean_normalized_error,
                s.sem_normalized_error, s.mean_percent_full_scale);
  }
  summary.commit();
  return 0;
}
