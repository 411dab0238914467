// The paper's Sec. IV experiments replayed on the simulator's marker fields at
// the default noise (0.0006 mm per axis per marker, the vision front end's
// measured error, sim_replay.hpp): translation, rotation, sliding linearity,
// stick/slip labels, contact region and the two accumulations, each against
// the figure. (test_pose_end_to_end.cpp repeats the main ones through
// rendered images.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "replay_metrics.hpp"

using namespace onetip;
using namespace onetip::poseval;

namespace {

const std::vector<ReplayFrame>& replayed(const std::string& name) {
  static std::map<std::string, std::vector<ReplayFrame>> cache;
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, replay(sampleScenario(name))).first;
  return it->second;
}

// The paper's translation range: |dx|, |dy| <= 1.5 mm, dz in [0, 3] mm.
bool inTranslationRange(const ReplayFrame& f) {
  return std::abs(f.gt.dx) <= 1.5 && std::abs(f.gt.dy) <= 1.5 && f.gt.dz >= 0 && f.gt.dz <= 3.0;
}

void print(const char* what, const AxisRmse& r) {
  std::printf("%-22s n=%3d  dx %.4f dy %.4f dz %.4f mm | yaw %.3f pitch %.3f roll %.3f deg\n", what, r.frames,
              r.rmse[0], r.rmse[1], r.rmse[2], r.rmse[3], r.rmse[4], r.rmse[5]);
}

}  // namespace

class Translation : public ::testing::TestWithParam<std::string> {};

// Issue: translation RMSE <= 0.05 mm per axis over |dx|, |dy| <= 1.5 mm and
// dz in [0, 3] mm, including the back-and-forth sweeps (turns at +-1.5 mm, at
// the edge of gross slip).
TEST_P(Translation, RmseWithinRange) {
  const auto r = axisRmse(replayed(GetParam()), composedOf, inTranslationRange);
  print(GetParam().c_str(), r);
  ASSERT_GT(r.frames, 40);
  for (size_t k = 0; k < 3; ++k) EXPECT_LE(r.rmse[k], 0.05) << "axis " << k;
}
INSTANTIATE_TEST_SUITE_P(Pose, Translation, ::testing::Values("press", "slide_x", "slide_y", "sweep_x", "sweep_y"));

class Rotation : public ::testing::TestWithParam<std::string> {};

// Issue: rotation RMSE <= 1.0 deg per axis over yaw in [-15, 15] and pitch,
// roll in [-40, 40] deg at 0.5 mm depth (paper: 2.6 deg roll/pitch, 1.8 deg yaw).
TEST_P(Rotation, RmseWithinWorkingRange) {
  const auto r = axisRmse(replayed(GetParam()), composedOf, [](const ReplayFrame& f) {
    return std::abs(f.gt.yaw) <= 15 && std::abs(f.gt.pitch) <= 40 && std::abs(f.gt.roll) <= 40;
  });
  print(GetParam().c_str(), r);
  ASSERT_GT(r.frames, 100);
  for (size_t k = 3; k < 6; ++k) EXPECT_LE(r.rmse[k], 1.0) << "axis " << k;
}
INSTANTIATE_TEST_SUITE_P(Pose, Rotation, ::testing::Values("twist", "pitch", "roll"));

class Sliding : public ::testing::TestWithParam<std::pair<std::string, int>> {};

// Sliding in x or y at 1 mm depth (gross slip from 1.5 mm): the issue asks for
// the output within 10% of the true displacement up to 3 mm (here with a
// 0.05 mm floor, the translation accuracy, for the first tenths of a mm).
TEST_P(Sliding, LinearUpToThreeMillimetres) {
  const auto [name, axis] = GetParam();
  int checked = 0;
  double worst = 0;
  for (const auto& f : replayed(name)) {
    if (!f.contact || !f.gt_contact || f.t < 0.7) continue;
    const double truth = f.gt.asArray()[static_cast<size_t>(axis)];
    if (truth <= 0 || truth > 3.0 || f.gt.dz < 0.8) continue;
    const double error = std::abs(f.composed.asArray()[static_cast<size_t>(axis)] - truth);
    worst = std::max(worst, error / std::max(truth, 0.5));
    EXPECT_LE(error, std::max(0.1 * truth, 0.05)) << name << " at " << truth << " mm";
    ++checked;
  }
  std::printf("%s: worst relative error %.3f over %d frames\n", name.c_str(), worst, checked);
  EXPECT_GT(checked, 50);
}
INSTANTIATE_TEST_SUITE_P(Pose, Sliding,
                         ::testing::Values(std::make_pair(std::string("slide_x"), 0),
                                           std::make_pair(std::string("slide_y"), 1)));

TEST(StickSlip, SlipMarkersF1OverTheSlideScenarios) {
  std::vector<ReplayFrame> all;
  for (const char* name : {"slide_x", "slide_y", "macro_slide"}) {
    const auto& f = replayed(name);
    const auto c = slipF1(f);
    std::printf("%-12s slip P %.3f R %.3f F1 %.3f\n", name, c.precision, c.recall, c.f1);
    all.insert(all.end(), f.begin(), f.end());
  }
  const auto c = slipF1(all);
  std::printf("pooled       slip P %.3f R %.3f F1 %.3f\n", c.precision, c.recall, c.f1);
  EXPECT_GE(c.f1, 0.9);
}

TEST(ContactRegion, IouAgainstTheTrueContact) {
  std::vector<ReplayFrame> all;
  for (const char* name : {"press", "slide_x", "slide_y", "sweep_x", "sweep_y", "macro_slide", "twist", "roll", "pitch"}) {
    const auto& f = replayed(name);
    std::printf("%-12s region IoU %.3f\n", name, regionIoU(f));
    all.insert(all.end(), f.begin(), f.end());
  }
  const double iou = regionIoU(all);
  std::printf("pooled       region IoU %.3f\n", iou);
  EXPECT_GE(iou, 0.9);
}

// The same measured increments accumulated two ways. On these single-axis
// scenarios the two differ only through estimation noise (the exact-increment
// comparison, where composition is exact and the Euler sum is not, is in
// test_input); composition must never be worse beyond 0.015 mm / 0.1 deg.
// (Largest gap measured: roll dz, composed 0.043 vs Euler 0.033 mm, where the
// simulator's marker-layer offset biases dx/dz of every rotation, README.)
TEST(Accumulation, CompositionAtLeastAsAccurateAsEulerSum) {
  const auto all = [](const ReplayFrame&) { return true; };
  for (const char* name : {"press", "slide_x", "sweep_y", "twist", "roll", "pitch", "demo_touch"}) {
    const auto c = axisRmse(replayed(name), composedOf, all);
    const auto e = axisRmse(replayed(name), eulerSumOf, all);
    std::printf("%-11s gap (euler - composed):", name);
    for (size_t k = 0; k < 6; ++k) {
      std::printf(" %+.4f", e.rmse[k] - c.rmse[k]);
      EXPECT_LE(c.rmse[k], e.rmse[k] + (k < 3 ? 0.015 : 0.1)) << name << " axis " << k;
    }
    std::printf("\n");
  }
}

// A finger tilting with its contact stuck (the core sticks; the rim starts to
// slip beyond ~20 deg) moves the markers 0.3 mm under the surface as the
// surface moves, not as the finger's body does (pose_accumulator.hpp). With the
// pad's marker depth the translation of c0 follows the finger over the first
// ramp to 30 deg (after the extremes the pitch estimate carries an error of its
// own); read at the marker layer it drifts by d sin(tilt) (0.15 mm at 30 deg).
TEST(Tilt, TheTranslationFollowsTheFingerNotTheMarkerLayer) {
  for (const char* name : {"pitch", "roll"}) {
    Recording rec = record(sampleScenario(name));
    ASSERT_GT(rec.marker_depth_mm, 0.2);
    const auto worstTranslation = [](const std::vector<ReplayFrame>& frames, int& checked) {
      double worst = 0;
      checked = 0;
      for (const ReplayFrame& f : frames) {  // the first ramp, up to 30 deg
        if (std::max(std::abs(f.gt.pitch), std::abs(f.gt.roll)) > 30) break;
        if (!f.contact) continue;
        ++checked;
        worst = std::max({worst, std::abs(f.raw.dx - f.gt.dx), std::abs(f.raw.dy - f.gt.dy),
                          std::abs(f.raw.dz - f.gt.dz)});
      }
      return worst;
    };
    int checked = 0;
    const double with_depth = worstTranslation(track(rec), checked);
    EXPECT_GT(checked, 30) << name;
    rec.marker_depth_mm = 0;
    int checked_flat = 0;
    const double at_markers = worstTranslation(track(rec), checked_flat);
    std::printf("%s: worst translation error up to 30 deg: %.4f mm (at the marker layer %.4f mm)\n", name,
                with_depth, at_markers);
    EXPECT_LE(with_depth, 0.02) << name;
    EXPECT_GT(at_markers, 0.1) << name;  // the effect is real: the same run read at the markers
  }
}

// At the pitch sweep's extremes (40 deg at 0.5 mm depth) the contact's stick
// set thins to three markers on a ten-marker contact, a line that fixes no
// pitch. Held at what the line fixes, one frame's pitch (0.9 deg) was lost at
// each extreme and the translation of c0 went 0.28 mm off by the end. A thin
// set of a contact too small to declare macroscopic slip, whose markers have
// been in the contact for the stick hold, gets Eq. 13-15 (model_selection.hpp).
TEST(Tilt, APitchSweepKeepsItsTranslationThroughTheExtremes) {
  double worst_mm = 0, worst_deg = 0;
  int checked = 0;
  for (const ReplayFrame& f : replayed("pitch")) {
    if (!f.contact || !f.gt_contact) continue;
    ++checked;
    worst_mm = std::max({worst_mm, std::abs(f.raw.dy - f.gt.dy), std::abs(f.raw.dz - f.gt.dz)});
    worst_deg = std::max(worst_deg, std::abs(f.raw.pitch - f.gt.pitch));
  }
  std::printf("pitch sweep: worst dy/dz error %.3f mm, worst pitch error %.2f deg over %d frames\n", worst_mm,
              worst_deg, checked);
  EXPECT_GT(checked, 180);
  EXPECT_LE(worst_mm, 0.15);
  EXPECT_LE(worst_deg, 0.7);
}
