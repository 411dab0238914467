// What the sensor measures about itself (pose/sensor_self_model.hpp) and the
// thresholds derived from it (pose/adaptive_pose_options.hpp), on synthetic
// marker fields with known noise, pitch and frame interval; and the model
// selection rules (pose/model_selection.hpp) on synthetic evidence.
#include <gtest/gtest.h>

#include <random>

#include "core/error.hpp"
#include "pose/adaptive_pose_options.hpp"
#include "pose/model_selection.hpp"
#include "pose/sensor_self_model.hpp"

using namespace onetip;
using namespace onetip::pose;

namespace {

MarkerField grid(int n, double pitch) {
  MarkerField f(n, n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) f.set(r * n + c, Eigen::Vector3d(c * pitch, r * pitch, 0));
  return f;
}

MarkerField noisy(const MarkerField& exact, double sigma, std::mt19937& rng) {
  std::normal_distribution<double> g(0, sigma);
  MarkerField out = exact;
  for (auto& p : out.position) p += Eigen::Vector3d(g(rng), g(rng), g(rng));
  return out;
}

}  // namespace

TEST(SensorSelfModel, MeasuresNoisePitchAndFrameIntervalOnRestFrames) {
  for (const double sigma : {0.0003, 0.0018}) {
    for (const double pitch : {0.8, 2.4}) {
      SensorSelfModel model;
      const MarkerField rest = grid(13, pitch);
      model.setRest(rest);
      std::mt19937 rng(3);
      for (int k = 0; k < 12; ++k) model.observe(noisy(rest, sigma, rng), k / 90.0, true);
      const SensorSelf& s = model.current();
      EXPECT_TRUE(s.noise_measured);
      EXPECT_NEAR(s.noise_mm, sigma, 0.1 * sigma) << "sigma " << sigma;
      EXPECT_NEAR(s.pitch_mm, pitch, 1e-9);
      EXPECT_NEAR(s.frame_s, 1 / 90.0, 1e-9);
    }
  }
}

TEST(SensorSelfModel, TheNoisiestAxisIsMeasuredBesideThePooledNoise) {
  // Through a stereo pair the depth is the noisiest axis (through the simulator's images z 0.0013 mm against x
  // and y 0.0002). The pooled sigma is then the lateral one; a bound on a marker's 3-D noise needs the depth's.
  SensorSelfModel model;
  const MarkerField rest = grid(13, 1.2);
  model.setRest(rest);
  std::mt19937 rng(5);
  std::normal_distribution<double> lateral(0, 0.0002), depth(0, 0.0013);
  for (int k = 0; k < 12; ++k) {
    MarkerField f = rest;
    for (auto& p : f.position) p += Eigen::Vector3d(lateral(rng), lateral(rng), depth(rng));
    model.observe(f, k / 90.0, true);
  }
  const SensorSelf& s = model.current();
  EXPECT_NEAR(s.largest_axis_noise_mm, 0.0013, 0.1 * 0.0013);
  EXPECT_LT(s.noise_mm, 0.0005);  // two thirds of the pooled components are lateral: their median is lateral
  // Isotropic noise: the largest axis is the pooled sigma, within the estimate's scatter.
  SensorSelfModel isotropic;
  isotropic.setRest(rest);
  for (int k = 0; k < 12; ++k) isotropic.observe(noisy(rest, 0.0006, rng), k / 90.0, true);
  EXPECT_NEAR(isotropic.current().largest_axis_noise_mm, 0.0006, 0.1 * 0.0006);
  EXPECT_GE(isotropic.current().largest_axis_noise_mm, isotropic.current().noise_mm * 0.95);
}

TEST(SensorSelfModel, FramesInContactDoNotCountAsNoiseAndLostMarkersAreSkipped) {
  SensorSelfModel model;
  const MarkerField rest = grid(9, 1.2);
  model.setRest(rest);
  std::mt19937 rng(5);
  model.observe(noisy(rest, 0.001, rng), 0.0, true);
  MarkerField pressed = noisy(rest, 0.001, rng);
  for (auto& p : pressed.position) p.z() -= 0.5;  // a press moves every marker: not noise
  model.observe(pressed, 0.1, false);
  EXPECT_FALSE(model.current().noise_measured);
  MarkerField lost = noisy(rest, 0.001, rng);
  for (size_t i = 0; i < lost.valid.size(); i += 2) lost.valid[i] = 0;
  model.observe(lost, 0.2, true);
  model.observe(noisy(rest, 0.001, rng), 0.3, true);
  EXPECT_TRUE(model.current().noise_measured);
  EXPECT_NEAR(model.current().noise_mm, 0.001, 0.15 * 0.001);
}

TEST(SensorSelfModel, PriorsHoldUntilMeasured) {
  SensorSelfOptions o;
  o.prior_noise_mm = 0.004;
  o.prior_frame_s = 0.01;
  SensorSelfModel model(o);
  EXPECT_EQ(model.current().noise_mm, 0.004);
  EXPECT_EQ(model.current().largest_axis_noise_mm, 0.004);
  EXPECT_EQ(model.current().frame_s, 0.01);
  o.window = 0;
  EXPECT_THROW(SensorSelfModel{o}, InputError);
}

TEST(EstimatorThresholds, ScaleWithNoisePitchAndFrameInterval) {
  const AdaptivePoseOptions o;
  SensorSelf base;  // 0.0006 mm, 1.2 mm, 30 fps: the operating point the defaults reproduce
  const EstimatorThresholds t = deriveThresholds(o, base);
  EXPECT_NEAR(t.slip_mm, 0.01, 1e-4);
  EXPECT_NEAR(t.robust_mm, 0.005, 1e-4);
  EXPECT_NEAR(t.min_spread_mm, 0.6, 1e-9);
  EXPECT_EQ(t.stick_hold_frames, 10);
  EXPECT_EQ(t.window_frames, 5);
  EXPECT_EQ(t.confirm_frames, 2);
  EXPECT_NEAR(t.macro_drift_mm, 0.08, 1e-3);
  EXPECT_NEAR(t.max_step_mm, 1.5, 1e-9);
  SensorSelf other = base;
  other.noise_mm *= 3;
  other.pitch_mm = 2.4;
  other.frame_s = 1 / 240.0;
  const EstimatorThresholds u = deriveThresholds(o, other);
  EXPECT_NEAR(u.slip_mm, 3 * t.slip_mm, 1e-12);
  EXPECT_NEAR(u.min_spread_mm, 2 * t.min_spread_mm, 1e-12);
  EXPECT_NEAR(u.macro_drift_mm, 2 * t.macro_drift_mm, 1e-12);
  EXPECT_EQ(u.stick_hold_frames, 80);  // the same 0.33 s
  EXPECT_EQ(u.window_frames, 38);      // the same 0.16 s
  EXPECT_EQ(u.confirm_frames, 16);     // the same 0.067 s
  EXPECT_NEAR(u.max_step_mm, t.max_step_mm / 8, 1e-12);
  other.noise_mm = 0.0001;  // quieter than the prior at rest: the prior holds
  EXPECT_NEAR(deriveThresholds(o, other).slip_mm, t.slip_mm, 1e-12);
}

TEST(EstimatorThresholds, OptionsOutsideTheirRangesAreRefusedByName) {
  AdaptivePoseOptions o;
  o.macro_window_s = 0;
  try {
    o.validate();
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("macro_window_s"), std::string::npos) << e.what();
  }
}

TEST(ModelSelection, FollowsEquation16AndTheStickSet) {
  ModelEvidence e;
  e.stick_fit_ok = true;
  e.rotation_supported = true;
  e.n_stick = 10;
  EXPECT_EQ(selectModel(e, ModelPolicy::adaptive), PoseModel::kabsch);  // full stick
  e.n_slip = 5;
  EXPECT_EQ(selectModel(e, ModelPolicy::adaptive), PoseModel::stick_slip);  // partial slip
  e.rotation_supported = false;
  EXPECT_EQ(selectModel(e, ModelPolicy::adaptive), PoseModel::kabsch);  // thin stick set: what it fixes
  e.slip_fixes_rotation = true;
  EXPECT_EQ(selectModel(e, ModelPolicy::adaptive), PoseModel::stick_slip);  // the slip markers fix the rest
  e.slip_fixes_rotation = false;
  e.n_stick = 1;
  e.n_slip = 2;  // 3 + 2 < 6: Eq. 16 fails
  EXPECT_EQ(selectModel(e, ModelPolicy::adaptive), PoseModel::centroid);
  e.n_slip = 3;  // 3 + 3 = 6: solvable
  e.rotation_supported = true;
  EXPECT_EQ(selectModel(e, ModelPolicy::adaptive), PoseModel::stick_slip);
  e.n_stick = 0;
  e.n_slip = 20;  // no stick marker at all
  EXPECT_EQ(selectModel(e, ModelPolicy::adaptive), PoseModel::centroid);
  e = ModelEvidence{true, true, 10, 0};
  EXPECT_EQ(selectModel(e, ModelPolicy::stick_slip_only), PoseModel::stick_slip);
  EXPECT_EQ(selectModel(e, ModelPolicy::centroid_only), PoseModel::centroid);
  EXPECT_EQ(selectModel(e, ModelPolicy::kabsch_only), PoseModel::kabsch);
  e.stick_fit_ok = false;
  EXPECT_EQ(selectModel(e, ModelPolicy::adaptive), PoseModel::centroid);
}

TEST(ModelSelection, AThinStickSetBelowTheCountIsTrustedOnlyOnASmallContactOnceSettled) {
  constexpr int kMinThin = 4;
  for (bool small : {false, true})
    for (bool settled : {false, true}) EXPECT_TRUE(thinStickSetTrusted(kMinThin, small, settled, kMinThin));
  EXPECT_TRUE(thinStickSetTrusted(3, true, true, kMinThin));    // a small contact's settled core
  EXPECT_FALSE(thinStickSetTrusted(3, true, false, kMinThin));  // markers just reached: the edge creeps
  EXPECT_FALSE(thinStickSetTrusted(3, false, true, kMinThin));  // a developed contact's last stuck markers
  EXPECT_FALSE(thinStickSetTrusted(2, false, false, kMinThin));
}
