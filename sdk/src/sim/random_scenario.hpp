// sim/random_scenario.hpp — seeded random combined-motion scenarios and
// random conditions, for campaigns that test an estimator outside the world it
// was tuned in.
//
// One seed gives one reproducible scenario (std::mt19937, the draws below in a
// fixed order), within the paper's working range:
//   conditions: contact model (halfspace | foundation, sim/pad.hpp), friction
//     mu in [0.5, 1.5], kinetic ratio in [0.6, 0.9] (foundation), layer
//     thickness in [4, 10] mm, foundation length l in [0.4, 1] x thickness,
//     marker depth in [0.1, 0.6] mm, marker grid n x n with n in
//     {9, 11, ..., 25} over the same 19.2 mm pad (square = 19.2 / (n - 1)),
//     indenter (finger ellipsoid scaled 0.7-1.3 x the 7 x 9 x 6 mm default,
//     sphere of radius 4-10 mm, 20 x 20 mm plate), image noise 1-6 grey levels,
//     blur 0-1.2 px, frame rate 15-240 fps (log-uniform), and the run's
//     fastest finger: 3-15 mm/s (a brisk slide: 4 mm in a third of a second)
//     and 10-60 deg/s (the paper's 40 deg pitch in 1.5 s is 27 deg/s);
//   motion: 1-3 contact episodes (re-touch at a new place); each presses to
//     0.4-2.5 mm (plate 0.3-1 mm), then runs 2-5 segments of 0.15-1.5 s (or
//     longer where the speed limits ask for it) towards random targets on all
//     axes at once (x, y within +-3.5 mm of the
//     touch-down point, yaw +-15 deg, pitch and roll +-30 deg; depth 0.4-3 mm;
//     the plate tilts +-8 deg, twists +-5 deg and does not slide: a flat plate
//     sliding over a flat pad in gross slip moves no footprint and is not
//     observable), so speeds, directions and reversals vary; a segment may
//     hold still; lift-off is sometimes taken while still sliding (lift-off in
//     mid-slip). With probability 0.15 (finger or sphere) a second, shallower
//     finger touches 6-7 mm away and may slide (two fingers; indenter 0 stays
//     the deeper one; the ground truth follows the finger touching most
//     nodes at onset, and the other once that one lifts: ground_truth.hpp).
// Keyframes are linear in time between targets (simulator: linear blend).
// World effects (sim/world_effects.hpp), only with `world_effects` set: drawn
// after everything above from a second generator seeded from the seed (so
// the scenario without them is the same, draw for draw, as without the
// flag), each on with probability 1/2: a viscoelastic gel (relaxation
// 0.1-0.4, time 0.05-5 s log-uniform); a camera shift of 1-5 px in a
// random direction, of both views or one, at a random time of the run, as a
// step or a ramp of 0.2-2 s; 1-5 % of the markers hidden; flicker of 0-10 %
// and an exposure step of -30..+30 % at a random time; rest drift (lateral
// strain -0.3..+0.3 %, offsets up to 0.05 mm, time constant 30-600 s).
// With `only` set, that one effect is on in every run and the others off,
// its size drawn from the same ranges (the same value as the full draw's
// where the effects drawn before it are off there too), so one effect's runs
// compare with their twins without it one cause at a time.
#pragma once

#include <optional>
#include <string>

#include "sim/scenario.hpp"

namespace onetip::sim {

struct RandomConditions {
  unsigned seed = 0;
  ContactModelKind model = ContactModelKind::halfspace;
  double friction = 1, kinetic_ratio = 1, thickness_mm = 7, foundation_length_mm = 0, marker_depth_mm = 0.3;
  int markers = 17;             // n of the n x n grid
  std::string indenter;         // finger | sphere | plate
  double noise_grey = 2, blur_px = 0, fps = 30;
  int episodes = 1;
  bool two_fingers = false;
  double peak_speed_mm_s = 0;   // fastest keyframe segment of indenter 0: translation...
  double peak_rate_deg_s = 0;   // ...and rotation
  bool world_effects = false;   // scenario.world drawn (see above)
};

struct RandomScenario {
  Scenario scenario;
  RandomConditions conditions;
};

enum class WorldEffect { creep, camera_shift, damage, light, drift };

RandomScenario randomScenario(unsigned seed, bool world_effects = false,
                              std::optional<WorldEffect> only = std::nullopt);

}  // namespace onetip::sim
