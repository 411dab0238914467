// Markers hidden for good (a tear or dirt that moves with the gel, sim/marker_damage.hpp) against the same
// run with every marker seen, on the simulator's ground truth: issue 38's "up to 5 % of the markers hidden for
// good: contact and pose figures within 10 % of the undamaged run". The motion is the world example's slide
// (tests/data/scenarios/world/damaged_gel.yaml: a press, 3 mm along S.x, a lift), with one listed marker two
// pitches beside the path, under the footprint's flank, where a sum that skips it pulls the footprint centre
// sideways while the finger passes (contact/lattice_hole.hpp), and 4.5 % more drawn at random. Measured over
// the 6 draws: translation RMSE 0.95-1.04 of the twin's (0.64-1.42 while the footprint centre skipped holes).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "replay_metrics.hpp"
#include "sim_replay.hpp"
#include "test_paths.hpp"

using namespace onetip;
using namespace onetip::poseval;

namespace {

sim::Scenario damagedGel() {
  return sim::loadScenario(std::string(test::sourceDir()) + "/tests/data/scenarios/world/damaged_gel.yaml");
}

// RMS over the frames both call contact of the 3-D translation error |(dx, dy, dz) - truth| (mm).
double translationRmse(const std::vector<ReplayFrame>& frames) {
  const AxisRmse a = axisRmse(frames, composedOf, [](const ReplayFrame&) { return true; });
  return std::sqrt(a.rmse[0] * a.rmse[0] + a.rmse[1] * a.rmse[1] + a.rmse[2] * a.rmse[2]);
}

}  // namespace

TEST(HiddenMarkers, FivePercentHiddenForGoodKeepTheSlidesTranslationWithinTenPercentOfTheUndamagedRun) {
  sim::Scenario undamaged = damagedGel();
  undamaged.world.damage = {};
  const std::vector<ReplayFrame> twin = replay(undamaged);
  const AxisRmse whole = axisRmse(twin, composedOf, [](const ReplayFrame&) { return true; });
  const double twin_translation = translationRmse(twin);
  ASSERT_GT(whole.frames, 60);
  const MarkerPattern pattern = undamaged.pad.pattern;
  const int first_touch = pattern.id(pattern.rows / 2, pattern.cols / 2);  // under the ellipsoid's tip at onset
  for (unsigned seed = 1; seed <= 6; ++seed) {
    sim::Scenario damaged = damagedGel();
    damaged.world.damage.ids = {pattern.id(pattern.rows / 2 + 2, pattern.cols / 2)};
    damaged.world.damage.fraction = 0.045;
    damaged.world.damage.seed = seed;
    const std::vector<int> hidden = damaged.world.damage.hiddenIds(pattern);
    ASSERT_LE(static_cast<double>(hidden.size()), 0.05 * pattern.count());
    // The truth's contact begins on the marker the finger touches first; hidden, the pad cannot see that frame
    // (docs/pose/README.md, "The rest, kept true"), so these draws leave it.
    ASSERT_EQ(std::count(hidden.begin(), hidden.end(), first_touch), 0) << "seed " << seed;
    const std::vector<ReplayFrame> frames = replay(damaged);
    const AxisRmse e = axisRmse(frames, composedOf, [](const ReplayFrame&) { return true; });
    std::printf("seed %u, %zu hidden: translation %.3f of the twin's, dx %.3f, dz %.3f\n", seed, hidden.size(),
                translationRmse(frames) / twin_translation, e.rmse[0] / whole.rmse[0], e.rmse[2] / whole.rmse[2]);
    EXPECT_GE(e.frames, whole.frames - 1) << "seed " << seed;
    EXPECT_NEAR(translationRmse(frames) / twin_translation, 1.0, 0.1) << "seed " << seed;
    EXPECT_NEAR(e.rmse[0] / whole.rmse[0], 1.0, 0.1) << "dx, seed " << seed;
    EXPECT_NEAR(e.rmse[2] / whole.rmse[2], 1.0, 0.1) << "dz, seed " << seed;
  }
}
