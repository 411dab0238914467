// tests/unit/sim/world_test_scenes.hpp — small scenes for the world-effect
// tests (sim/world_effects.hpp): a sphere held above the pad or pressed by
// steps at given times, built in code so each test states its own timing.
#pragma once

#include <utility>
#include <vector>

#include "sim/scenario.hpp"

namespace onetip::sim::testsupport {

// A 6 mm sphere at the pad's centre following (t, depth) keyframes (depth < 0:
// above the pad), noise-free images unless asked.
inline Scenario sphereScene(const std::vector<std::pair<double, double>>& depth_keys, double fps = 30) {
  Scenario sc;
  sc.name = "world_effects_test";
  sc.fps = fps;
  sc.image.noise_sigma = 0;
  IndenterTrack track;
  track.geometry.shape = IndenterShape::sphere;
  track.geometry.semi_axes = {6, 6, 6};
  for (const auto& [t, depth] : depth_keys) {
    Keyframe k;
    k.t = t;
    k.depth = depth;
    track.keyframes.push_back(k);
  }
  sc.indenters.push_back(track);
  return sc;
}

}  // namespace onetip::sim::testsupport
