// The paper's 27-condition objective evaluation in simulation, shortened
// (25 Hz, one repetition; onetip on a coarse 15-deg grid), and the trends of
// its Fig. 7 that this simulation really reproduces (docs/haptics/README.md
// says which do not, and why):
//   BioTac-like: error falls with more device DoF in every condition and with a
//     finer step at every DoF and n; at 2- and 3-DoF, n = 4 and 8 beat n = 1 and
//     n = 8 narrows the gap between the finest and coarsest step. At 1-DoF more
//     neighbours do not help (the 1-D curve of the device cannot reach the
//     side contacts, and averaging along it moves away from its nearest point).
//     With the side interactions' plate tilt at 0 (every remote contact is a
//     flat press the device can reproduce), n = 4 beats n = 1 at every DoF and
//     step, and n = 8 beats it on average over the steps at every DoF (at
//     1-DoF, 8 rows span 24-72 deg of the 1-D curve, and at 6 deg n = 8 is
//     level with n = 1: 0.0538 vs 0.0541 in the full run, 0.0527 vs 0.0521 in
//     this shortened one); docs/haptics/neighbor_benefit.png shows the sweep.
//   onetip 5 x 5 grid: error falls with more DoF and, at 3-DoF, with a finer step.
// The best condition's error as % of full scale is reported beside the paper's 3.0%.
// The servo option (servo_response.hpp) is checked to sit between renderer and device.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <tuple>

#include "haptics/biotac_like_sensor.hpp"
#include "haptics/display_grid.hpp"
#include "haptics/objective_evaluation.hpp"
#include "haptics/onetip_contact_sensor.hpp"
#include "sanitizer_leg.hpp"

using namespace onetip::haptics;

namespace {
using Key = std::tuple<double, int, int>;  // step, n, dof
std::map<Key, ConditionSummary> byCondition(const std::vector<EvaluationRow>& rows) {
  std::map<Key, ConditionSummary> out;
  for (const auto& s : summarizeByCondition(rows))
    out[{s.condition.step_deg, s.condition.neighbors, static_cast<int>(s.condition.dof)}] = s;
  return out;
}
double meanOver(const std::map<Key, ConditionSummary>& c, const std::function<bool(const Key&)>& pick) {
  double sum = 0.0;
  int count = 0;
  for (const auto& [k, s] : c)
    if (pick(k)) sum += s.mean_normalized_error, ++count;
  return sum / count;
}

// The shortened BioTac-like evaluation (2 counts of noise; collection, remote
// and in-device sensors with their own noise seeds).
std::vector<EvaluationRow> runBiotacEvaluation(double side_tilt_deg,
                                               const std::optional<ServoResponseOptions>& servo = {}) {
  BiotacLikeOptions o;
  o.noise_counts = 2.0;
  const BiotacLikeEvaluationSensors sensors(o);
  const PlatformKinematics device;
  const TactileDataset full = simulateDataset(device, sensors.collection, 3.0);
  ObjectiveEvaluationOptions options;
  options.interactions.rate_hz = 25.0;
  options.interactions.repetitions = 1;
  options.interactions.side_tilt_deg = side_tilt_deg;
  options.servo = servo;
  return runObjectiveEvaluation(full, sensors.remote, sensors.in_device, device, options);
}
}  // namespace

TEST(ObjectiveEvaluation, BiotacErrorFallsWithMoreDofAFinerStepAndMoreNeighbours) {
  ONETIP_SWEEP_RUNS_IN_RELEASE_ONLY();
  const auto rows = runBiotacEvaluation(InteractionOptions{}.side_tilt_deg);
  ASSERT_EQ(rows.size(), 27u * 6u);
  const auto c = byCondition(rows);
  ASSERT_EQ(c.size(), 27u);
  auto e = [&](double step, int n, int d) { return c.at({step, n, d}).mean_normalized_error; };

  for (double step : {3.0, 6.0, 9.0})
    for (int n : {1, 4, 8}) {
      EXPECT_GT(e(step, n, 1), e(step, n, 2)) << step << " deg, n = " << n;
      EXPECT_GT(e(step, n, 2), e(step, n, 3)) << step << " deg, n = " << n;
    }
  for (int d : {1, 2, 3}) {
    for (int n : {1, 4, 8}) EXPECT_LT(e(3, n, d), e(9, n, d)) << d << "-DoF, n = " << n;
    auto step = [&](double s) {
      return meanOver(c, [s, d](const Key& k) { return std::get<0>(k) == s && std::get<2>(k) == d; });
    };
    EXPECT_LT(step(3), step(6)) << d << "-DoF";
    EXPECT_LT(step(6), step(9)) << d << "-DoF";
  }
  for (int d : {2, 3}) {
    for (double step : {3.0, 6.0, 9.0}) {
      EXPECT_GT(e(step, 1, d), e(step, 4, d)) << step << " deg, " << d << "-DoF";
      EXPECT_GT(e(step, 1, d), e(step, 8, d)) << step << " deg, " << d << "-DoF";
    }
    EXPECT_LT(e(9, 8, d) - e(3, 8, d), e(9, 1, d) - e(3, 1, d)) << d << "-DoF";
  }

  double best = 1e9;
  for (const auto& [k, s] : c) best = std::min(best, s.mean_percent_full_scale);
  // Paper: 3.0% of the 12-bit full scale in its best condition. The simulation
  // has no sensor drift or placement error, so it must do at least as well.
  EXPECT_LT(best, 3.0);
  RecordProperty("best_percent_full_scale", std::to_string(best));
}

TEST(ObjectiveEvaluation, BiotacMoreNeighboursHelpWhenEveryRemoteContactIsReachable) {
  ONETIP_SWEEP_RUNS_IN_RELEASE_ONLY();
  const auto c = byCondition(runBiotacEvaluation(0.0));
  auto e = [&](double step, int n, int d) { return c.at({step, n, d}).mean_normalized_error; };
  for (int d : {1, 2, 3}) {
    for (double step : {3.0, 6.0, 9.0}) EXPECT_GT(e(step, 1, d), e(step, 4, d)) << step << " deg, " << d << "-DoF";
    auto neighbours = [&](int n) {
      return meanOver(c, [n, d](const Key& k) { return std::get<1>(k) == n && std::get<2>(k) == d; });
    };
    EXPECT_GT(neighbours(1), neighbours(8)) << d << "-DoF";
  }
}

// The servo option really sits between the renderer and the device: servos
// that take every command at once and move without limit reproduce the
// instantaneous device exactly; the paper's servos lag, which costs a little
// (docs/haptics: +0.1-1.7 % per DoF in the full run).
TEST(ObjectiveEvaluation, ServoDynamicsSitBetweenTheRendererAndTheDevice) {
  ONETIP_SWEEP_RUNS_IN_RELEASE_ONLY();
  const double tilt = InteractionOptions{}.side_tilt_deg;
  const auto instant = runBiotacEvaluation(tilt);
  ServoResponseOptions ideal;
  ideal.control_rate_hz = 1000.0;
  ideal.resolution_deg = 0.0;
  ideal.max_speed_deg_s = 1e9;
  const auto ideal_rows = runBiotacEvaluation(tilt, ideal);
  ASSERT_EQ(ideal_rows.size(), instant.size());
  for (size_t i = 0; i < instant.size(); ++i) EXPECT_EQ(ideal_rows[i].normalized_error, instant[i].normalized_error);

  const auto c_instant = byCondition(instant);
  const auto c_paper = byCondition(runBiotacEvaluation(tilt, ServoResponseOptions{}));
  const auto all = [](const Key&) { return true; };
  EXPECT_GT(meanOver(c_paper, all), meanOver(c_instant, all));
  EXPECT_LT(meanOver(c_paper, all), 1.05 * meanOver(c_instant, all));
}

TEST(ObjectiveEvaluation, OnetipErrorFallsWithMoreDofAndAFinerStep) {
  ONETIP_SWEEP_RUNS_IN_RELEASE_ONLY();
  const OnetipContactSensor sensor;  // deterministic: one instance serves all three roles
  const PlatformKinematics device;
  const TactileDataset full = simulateDataset(device, sensor, 15.0);  // 1,331 rows
  ObjectiveEvaluationOptions options;
  options.steps_deg = {15.0, 30.0};
  options.neighbors = {1, 4};
  options.interactions.rate_hz = 5.0;
  options.interactions.repetitions = 1;
  const auto c = byCondition(runObjectiveEvaluation(full, sensor, sensor, device, options));
  ASSERT_EQ(c.size(), 12u);
  auto dof = [&](int d) { return meanOver(c, [d](const Key& k) { return std::get<2>(k) == d; }); };
  EXPECT_GT(dof(1), dof(2));
  EXPECT_GT(dof(2), dof(3));
  for (int n : {1, 4}) EXPECT_LT(c.at({15.0, n, 3}).mean_normalized_error, c.at({30.0, n, 3}).mean_normalized_error);
  for (const auto& [k, s] : c) {
    EXPECT_GT(s.mean_percent_full_scale, 0.0);
    EXPECT_LT(s.mean_percent_full_scale, 100.0);
  }
}
