// The paper's 27-condition objective evaluation in simulation (a shortened
// recording: 10 Hz, one repetition): the trends the simulation reproduces —
// error falls with more device DoF and with more neighbours — and the best
// condition's error as % of full scale beside the paper's 3.0%.
#include <gtest/gtest.h>

#include <map>

#include "haptics/biotac_like_sensor.hpp"
#include "haptics/display_grid.hpp"
#include "haptics/objective_evaluation.hpp"

using namespace onetip::haptics;

TEST(ObjectiveEvaluation, ErrorFallsWithMoreDofAndMoreNeighbours) {
  BiotacLikeOptions o;
  o.noise_counts = 2.0;
  const BiotacLikeSensor collection(o);
  o.seed = 2;
  const BiotacLikeSensor remote(o);
  o.seed = 3;
  const BiotacLikeSensor in_device(o);
  const PlatformKinematics device;
  const TactileDataset full = simulateDataset(device, collection, 3.0);
  ObjectiveEvaluationOptions options;
  options.interactions.rate_hz = 10.0;
  options.interactions.repetitions = 1;
  const auto rows = runObjectiveEvaluation(full, remote, in_device, device, options);
  ASSERT_EQ(rows.size(), 27u * 6u);
  const auto summary = summarizeByCondition(rows);
  ASSERT_EQ(summary.size(), 27u);

  std::map<int, double> by_dof, by_n;
  double best = 1e9;
  for (const auto& s : summary) {
    by_dof[static_cast<int>(s.condition.dof)] += s.mean_normalized_error / 9.0;
    by_n[s.condition.neighbors] += s.mean_normalized_error / 9.0;
    best = std::min(best, s.mean_percent_full_scale);
  }
  EXPECT_GT(by_dof[1], by_dof[2]);
  EXPECT_GT(by_dof[2], by_dof[3]);
  EXPECT_GT(by_n[1], by_n[4]);
  EXPECT_GT(by_n[4], by_n[8]);
  // Paper: 3.0% of the 12-bit full scale in its best condition. The simulation
  // has no sensor drift or placement error, so it must do at least as well.
  EXPECT_LT(best, 3.0);
  RecordProperty("best_percent_full_scale", std::to_string(best));
  for (const auto& r : rows) {
    EXPECT_GE(r.normalized_error, 0.0);
    EXPECT_GT(r.dataset_rows, 0u);
  }
}
