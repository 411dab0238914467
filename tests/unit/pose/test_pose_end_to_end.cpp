// The accuracy figures end to end: simulator frames rendered at the
// default image noise, through pipeline::FrameProcessor (corners, tracking,
// triangulation, contact, stick/slip, pose) against the simulator's ground
// truth. Press, slide_x and sweep_x at their 30 fps; roll, pitch and twist at 15 fps (the
// same motion in half the frames, to keep the rendering time down).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>

#include "rendered_replay.hpp"
#include "replay_metrics.hpp"
#include "sanitizer_leg.hpp"

using namespace onetip;
using namespace onetip::poseval;

namespace {

const RenderedReplay& rendered(const std::string& name) {
  static std::map<std::string, RenderedReplay> cache;
  auto it = cache.find(name);
  if (it == cache.end()) {
    const double fps = name == "roll" || name == "pitch" || name == "twist" ? 15 : 0;
    it = cache.emplace(name, replayRendered(sampleScenario(name), fps)).first;
    const RenderedReplay& r = it->second;
    std::printf("%-8s %zu frames (%d lost), marker error RMS x %.5f y %.5f z %.5f mm\n", name.c_str(), r.frames.size(),
                r.lost_frames, r.marker_rmse_mm[0], r.marker_rmse_mm[1], r.marker_rmse_mm[2]);
  }
  return it->second;
}

bool inTranslationRange(const ReplayFrame& f) {
  return std::abs(f.gt.dx) <= 1.5 && std::abs(f.gt.dy) <= 1.5 && f.gt.dz >= 0 && f.gt.dz <= 3.0;
}

bool inRotationRange(const ReplayFrame& f) {
  return std::abs(f.gt.yaw) <= 15 && std::abs(f.gt.pitch) <= 40 && std::abs(f.gt.roll) <= 40;
}

void print(const std::string& what, const AxisRmse& r) {
  std::printf("%-8s end to end n=%3d  dx %.4f dy %.4f dz %.4f mm | yaw %.3f pitch %.3f roll %.3f deg\n", what.c_str(),
              r.frames, r.rmse[0], r.rmse[1], r.rmse[2], r.rmse[3], r.rmse[4], r.rmse[5]);
}

}  // namespace

// The rendered replay of `name` keeps every frame, and its RMSE over the
// frames `keep` accepts stays within `limit` on axes [first, first + 3).
static void expectRmse(const std::string& name, const FramePredicate& keep, size_t first, double limit) {
  const RenderedReplay& r = rendered(name);
  EXPECT_EQ(r.lost_frames, 0);
  const auto e = axisRmse(r.frames, rawOf, keep);
  print(name, e);
  ASSERT_GT(e.frames, 40);
  for (size_t k = first; k < first + 3; ++k) EXPECT_LE(e.rmse[k], limit) << "axis " << k;
}

class EndToEndTranslation : public ::testing::TestWithParam<std::string> {};

// Issue: translation RMSE <= 0.05 mm per axis over |dx|, |dy| <= 1.5 mm, dz in [0, 3] mm. sweep_x pins
// the creep test (pose/stick_set_creep.hpp): without it, at the end of the +1.5 mm stroke a stick set of
// creeping markers carried the estimate and 0.2 mm were lost to the end.
TEST_P(EndToEndTranslation, RmseWithinRange) {
  ONETIP_SWEEP_RUNS_IN_RELEASE_ONLY();
  expectRmse(GetParam(), inTranslationRange, 0, 0.05);
}
INSTANTIATE_TEST_SUITE_P(Pose, EndToEndTranslation, ::testing::Values("press", "slide_x", "sweep_x"));

class EndToEndRotation : public ::testing::TestWithParam<std::string> {};

// Issue: rotation RMSE <= 1.0 deg per axis over yaw in [-15, 15], pitch and roll in [-40, 40] (0.5 mm
// depth). Pitch pins the noise floor of the thresholds: with the rest jitter alone it froze at 34 deg.
TEST_P(EndToEndRotation, RmseWithinWorkingRange) {
  ONETIP_SWEEP_RUNS_IN_RELEASE_ONLY();
  expectRmse(GetParam(), inRotationRange, 3, 1.0);
}
INSTANTIATE_TEST_SUITE_P(Pose, EndToEndRotation, ::testing::Values("roll", "pitch", "twist"));

// Issue: sliding in x stays within 10% of the true displacement up to 3 mm
// (with a 0.05 mm floor, the translation accuracy, for the first tenths).
TEST(EndToEndSliding, LinearUpToThreeMillimetres) {
  ONETIP_SWEEP_RUNS_IN_RELEASE_ONLY();
  int checked = 0;
  for (const auto& f : rendered("slide_x").frames) {
    if (!f.contact || !f.gt_contact || f.t < 0.7 || f.gt.dx <= 0 || f.gt.dx > 3.0 || f.gt.dz < 0.8) continue;
    EXPECT_LE(std::abs(f.raw.dx - f.gt.dx), std::max(0.1 * f.gt.dx, 0.05)) << "at " << f.gt.dx << " mm";
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

// The field-level tests imitate the front end with 0.0006 mm per axis
// (sim_replay.hpp); the rendered path must not be much noisier than that.
TEST(EndToEndMarkers, FrontEndErrorMatchesTheFieldLevelNoise) {
  ONETIP_SWEEP_RUNS_IN_RELEASE_ONLY();
  const RenderedReplay& r = rendered("press");
  for (int k = 0; k < 3; ++k) EXPECT_LE(r.marker_rmse_mm[k], 0.0015) << "axis " << k;
}
