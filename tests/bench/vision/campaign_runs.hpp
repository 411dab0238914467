// tests/bench/vision/campaign_runs.hpp — the image-level runs of the front-end
// campaign (issue 16), built in code as simulator scenarios.
//
// Every run presses the default finger (ellipsoid 7 x 9 x 6 mm) into a pad of
// n x n markers over the same 19.2 mm extent (square_mm = 19.2 / (n - 1),
// n = 9..25), rendered at 30 fps with image noise 1..6 grey levels and optical
// blur 0..1.2 px. Kinds (speeds are given in squares per frame, so the same
// value is the same challenge to the tracker at every density):
//   slide    press 1 mm, slide +-4 squares along x or y with two reversals;
//   shear    press 2 mm at friction 2, slide 3 squares and straight back
//            (heavy shear, then a reversal of the whole stuck region);
//   tilt     press 1.5 mm, roll and pitch to +-35 deg and back;
//   combined press, slide, twist 15 deg and tilt 25 deg at once, then back.
// Seeds, densities, noise and blur cycle over the runs so that each kind sees
// each density. Units: mm, degrees, frames at 30 fps.
// randomRuns: sim::randomScenario(seed) for seeds 1..count (random combined
// motion, conditions and contact model, sim/random_scenario.hpp), each cut to
// its first max_frames frames.
#pragma once

#include <string>
#include <vector>

#include "sim/scenario.hpp"

namespace onetip::bench {

struct CampaignRun {
  std::string kind;          // slide, shear, tilt, combined, random
  double speed_sq = 0;       // commanded finger speed, squares per frame (0: not a speed run)
  sim::Scenario scenario;
  int max_frames = 0;        // 0: the whole scenario
};

// One run of a kind; `index` picks its conditions: density n = 9, 13, 17,
// 21, 25 for index % 5 = 0..4, noise 1 + (7 index % 6) grey levels, blur
// 0.4 x ((5 index / 3) % 4) px, seed 1000 + index.
CampaignRun slideRun(int index, double speed_sq, bool along_y);
CampaignRun shearRun(int index, double speed_sq);

// The scripted runs: every kind at speeds 0.1..1.0 squares per frame.
std::vector<CampaignRun> scriptedRuns();
std::vector<CampaignRun> randomRuns(int count, int max_frames);

}  // namespace onetip::bench
