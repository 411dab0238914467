// The stick-label oracle (stick_oracle.hpp) with the truth's labels on shipped scenarios, against the
// observable truth: where plenty of markers stick they alone follow the motion to the noise; the sliding
// markers' normal residuals fix a turn a small sticking core does not, and bias a tilt where the contact's
// edge bends the marker layer (decision record 0018); unless they carry their slide's model error, they turn
// a finger that slides fast on a few sticking markers (decision record 0019).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "observable_truth.hpp"
#include "campaign_score.hpp"
#include "sim/random_scenario.hpp"
#include "sliding_surface.hpp"
#include "replay_metrics.hpp"
#include "sim_replay.hpp"
#include "stick_oracle.hpp"

using namespace onetip;
using namespace onetip::poseval;

namespace {

// RMS of the oracle's error against the observable truth over the frames in contact.
AxisRmse oracleError(const std::string& scenario, bool slip_normals, OracleLabels labels = OracleLabels::truth,
                     bool reweight = false) {
  const ReplayOptions options;
  const Recording recording = record(sampleScenario(scenario), options);
  std::vector<ReplayFrame> frames = track(recording, options.tracker);
  StickOracleOptions oracle{options.noise_mm, labels, slip_normals};
  oracle.reweight = reweight;
  applyStickOracle(recording, frames, oracle);
  const std::vector<Input6> reference = observableTruth(frames);
  for (size_t k = 0; k < frames.size(); ++k) frames[k].gt = reference[k];
  return axisRmse(frames, composedOf, [](const ReplayFrame& f) { return f.gt_contact; });
}

}  // namespace

TEST(StickOracle, WherePlentyOfMarkersStickTheyAloneFollowTheMotionToTheNoise) {
  // A press (every marker under the finger sticks), a plate's combined motion and a slide into gross slip.
  for (const char* name : {"press", "complex", "macro_slide"}) {
    const AxisRmse e = oracleError(name, false);
    std::printf("%s: dx %.4f dy %.4f dz %.4f mm, yaw %.3f pitch %.3f roll %.3f deg\n", name, e.rmse[0], e.rmse[1],
                e.rmse[2], e.rmse[3], e.rmse[4], e.rmse[5]);
    ASSERT_GT(e.frames, 10) << name;
    for (size_t a = 0; a < 3; ++a) EXPECT_LE(e.rmse[a], 0.005) << name << " axis " << a;
    // Measured 0.001-0.036 deg (GCC release build) and 0.001-0.057 deg (Clang sanitizer build: other noise bits).
    for (size_t a = 3; a < 6; ++a) EXPECT_LE(e.rmse[a], 0.1) << name << " axis " << a;
  }
}

TEST(StickOracle, TheTruncatedCostAfterPerfectLabelsKeepsATwistButLetsAYoungPressGoAtOnce) {
  // The truth's labels, then every marker its cheapest case under the truncated cost (decision record
  // 0020). A twist's sticking core keeps carrying the finger. In the press's second frame of contact the
  // labelled solve, with four markers newly touching (their normal residuals in it), reads the press 7 um
  // short, so the five sticking markers lie beyond the bound (2.9 um) of their anchors: all five are let go
  // at once, the frame is solved from nothing that sticks, and its 0.046 mm of press is lost for good
  // (anchored registration would have taken it back the next frame).
  // The twist, which begins with a press, loses its depth the same way (dz 0.053 mm); its turn and slide
  // are kept.
  const AxisRmse twist = oracleError("twist", true, OracleLabels::truth, true);
  std::printf("twist, the truth's labels reweighted: dx %.4f dy %.4f dz %.4f mm, yaw %.3f pitch %.3f roll %.3f deg\n",
              twist.rmse[0], twist.rmse[1], twist.rmse[2], twist.rmse[3], twist.rmse[4], twist.rmse[5]);
  ASSERT_GT(twist.frames, 10);
  for (size_t a = 0; a < 2; ++a) EXPECT_LE(twist.rmse[a], 0.005) << "axis " << a;
  for (size_t a = 3; a < 6; ++a) EXPECT_LE(twist.rmse[a], 0.1) << "axis " << a;
  const AxisRmse kept = oracleError("press", true), reweighted = oracleError("press", true, OracleLabels::truth, true);
  std::printf("press dz: %.4f mm with the truth's labels, %.4f reweighted\n", kept.rmse[2], reweighted.rmse[2]);
  EXPECT_LE(kept.rmse[2], 0.01);  // measured 0.0058 mm
  EXPECT_GT(reweighted.rmse[2], 5 * kept.rmse[2]);
}

TEST(StickOracle, SlidingMarkersNormalsFixATurnThatAFewStickingMarkersDoNot) {
  // A twist: the sticking core is small and the slipping ring wide; the ring's normals fix the tilt.
  const AxisRmse without = oracleError("twist", false), with = oracleError("twist", true);
  std::printf("twist roll: %.3f deg without the normal residuals, %.3f with\n", without.rmse[5], with.rmse[5]);
  EXPECT_LT(with.rmse[5], without.rmse[5] / 5);
  EXPECT_LE(with.rmse[5], 0.05);
}

TEST(StickOracle, SlidingMarkersNormalsBiasAPlateTiltedAboutItsEdge) {
  const AxisRmse without = oracleError("tip_flat_tip", false), with = oracleError("tip_flat_tip", true);
  std::printf("tip_flat_tip pitch: %.3f deg without the normal residuals, %.3f with\n", without.rmse[4],
              with.rmse[4]);
  EXPECT_GT(with.rmse[4], 5 * without.rmse[4]);
}

TEST(SlidingSurface, ASlideAlongTheSurfaceAddsItsShareToTheNoiseAndAMoveAlongTheNormalDoesNot) {
  const Eigen::Vector3d n = Eigen::Vector3d::UnitZ();
  EXPECT_DOUBLE_EQ(slidingSurfaceSd(0.001, Eigen::Vector3d::Zero(), n, 0.05), 0.001);
  EXPECT_DOUBLE_EQ(slidingSurfaceSd(0.001, Eigen::Vector3d(0, 0, 0.3), n, 0.05), 0.001);  // that is the residual
  // A 0.2 mm slide at f = 0.05 departs by 0.01 mm: u = sqrt(0.001^2 + 0.01^2).
  EXPECT_NEAR(slidingSurfaceSd(0.001, Eigen::Vector3d(0.12, 0.16, 0.05), n, 0.05), std::hypot(0.001, 0.01), 1e-15);
}

TEST(StickOracle, SlidingMarkersNormalsTurnAFewStickingMarkersUnlessTheyCarryTheSlidesError) {
  // A random campaign run: a sphere on a coarse 9 x 9 pattern (1.2 um noise) slides and turns with few
  // markers sticking. With the noise alone as their sd, the sliding markers' normal residuals (each off by a
  // few um under the true motion, mostly with the same sign) outweigh the sticking markers and turn the
  // sphere 11 deg off what the pad sees; with their slide's model error about 2 deg.
  const unsigned seed = 253;
  const sim::RandomScenario rs = sim::randomScenario(seed);
  ReplayOptions options;
  options.noise_mm = 0.0003 * rs.conditions.noise_grey;
  options.seed = seed;
  const Recording recording = record(rs.scenario, options);
  const auto worstTurnError = [&](bool sliding_error) {
    std::vector<ReplayFrame> frames = track(recording, options.tracker);
    StickOracleOptions oracle{options.noise_mm, OracleLabels::truth, true};
    oracle.sliding_model_error = sliding_error;
    applyStickOracle(recording, frames, oracle);
    const std::vector<Input6> reference = observableTruth(frames);
    double worst = 0;
    for (size_t k = 0; k < frames.size(); ++k)
      if (frames[k].gt_contact)
        for (double e : {frames[k].raw.yaw - reference[k].yaw, frames[k].raw.pitch - reference[k].pitch,
                         frames[k].raw.roll - reference[k].roll})
          worst = std::max(worst, std::abs(e));
    return worst;
  };
  const double noise_only = worstTurnError(false), with_error = worstTurnError(true);
  std::printf("worst turn error: %.2f deg with the noise alone, %.2f with the slide's error\n", noise_only,
              with_error);
  EXPECT_GT(noise_only, 5.0);
  EXPECT_LT(with_error, noise_only / 2);
}
