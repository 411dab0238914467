#include "sim/random_scenario.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace onetip::sim {

namespace {

class Draw {
 public:
  explicit Draw(unsigned seed) : rng_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  bool chance(double p) { return uniform(0, 1) < p; }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  double logUniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }

 private:
  std::mt19937 rng_;
};

struct Limits {
  double slide_mm, yaw_deg, tilt_deg, depth_min, depth_max;
  double speed_mm_s, rate_deg_s;  // this run's fastest finger
};

// A segment lasts its drawn time or longer, so no axis moves faster than the run's limits.
double segmentTime(const Limits& lim, const Keyframe& a, const Keyframe& b, double drawn) {
  const double travel = std::hypot(b.x - a.x, b.y - a.y, b.depth - a.depth);
  const double turn = std::max({std::abs(b.yaw - a.yaw), std::abs(b.pitch - a.pitch), std::abs(b.roll - a.roll)});
  return std::max({drawn, travel / lim.speed_mm_s, turn / lim.rate_deg_s});
}

// One contact episode of the main indenter, appended to `track` from time t;
// returns the time the indenter is clear of the pad again.
double appendEpisode(Draw& d, const Limits& lim, IndenterTrack& track, double t) {
  Keyframe k;
  k.t = t;
  k.x = d.uniform(-1.5, 1.5);
  k.y = d.uniform(-1.5, 1.5);
  k.depth = -0.3;
  if (!track.keyframes.empty() && track.keyframes.back().t >= t) k.t = track.keyframes.back().t + 0.05;
  track.keyframes.push_back(k);
  const double x0 = k.x, y0 = k.y;
  Keyframe prev = k;
  k.depth = d.uniform(lim.depth_min, std::min(lim.depth_max, 2.5));
  k.t += segmentTime(lim, prev, k, d.uniform(0.2, 0.6));
  track.keyframes.push_back(k);
  const int segments = d.integer(2, 5);
  for (int s = 0; s < segments; ++s) {
    prev = k;
    const double drawn = d.uniform(0.15, 1.5);
    if (!d.chance(0.15)) {  // else hold still
      if (d.chance(0.7)) k.x = x0 + d.uniform(-lim.slide_mm, lim.slide_mm);
      if (d.chance(0.7)) k.y = y0 + d.uniform(-lim.slide_mm, lim.slide_mm);
      if (d.chance(0.6)) k.yaw = d.uniform(-lim.yaw_deg, lim.yaw_deg);
      if (d.chance(0.6)) k.pitch = d.uniform(-lim.tilt_deg, lim.tilt_deg);
      if (d.chance(0.6)) k.roll = d.uniform(-lim.tilt_deg, lim.tilt_deg);
      if (d.chance(0.5)) k.depth = d.uniform(lim.depth_min, lim.depth_max);
    }
    k.t = prev.t + segmentTime(lim, prev, k, drawn);
    track.keyframes.push_back(k);
  }
  // Lift-off, sometimes while still sliding.
  prev = k;
  const double drawn = d.uniform(0.1, 0.4);
  if (lim.slide_mm > 0 && d.chance(0.4)) {
    k.x += d.uniform(-1.0, 1.0);
    k.y += d.uniform(-1.0, 1.0);
  }
  k.depth = -0.3;
  k.t = prev.t + segmentTime(lim, prev, k, drawn);
  track.keyframes.push_back(k);
  // Back to upright before the next touch.
  k.t += 0.1;
  k.yaw = k.pitch = k.roll = 0;
  track.keyframes.push_back(k);
  return k.t;
}

void measureSpeeds(const IndenterTrack& track, RandomConditions& c) {
  for (size_t i = 1; i < track.keyframes.size(); ++i) {
    const Keyframe &a = track.keyframes[i - 1], &b = track.keyframes[i];
    const double dt = b.t - a.t;
    if (a.depth < 0 && b.depth < 0) continue;
    c.peak_speed_mm_s = std::max(c.peak_speed_mm_s, std::hypot(b.x - a.x, b.y - a.y, b.depth - a.depth) / dt);
    c.peak_rate_deg_s =
        std::max(c.peak_rate_deg_s, std::max({std::abs(b.yaw - a.yaw), std::abs(b.pitch - a.pitch),
                                              std::abs(b.roll - a.roll)}) / dt);
  }
}

// The world effects, each on with probability 1/2 (random_scenario.hpp).
WorldEffects drawWorldEffects(Draw& d, double duration, std::optional<WorldEffect> only) {
  WorldEffects w;
  const auto on = [&](WorldEffect e) {
    const bool drawn = d.chance(0.5);
    return only ? *only == e : drawn;
  };
  if (on(WorldEffect::creep)) {
    w.viscoelastic.relaxation = d.uniform(0.1, 0.4);
    w.viscoelastic.time_s = d.logUniform(0.05, 5);
  }
  if (on(WorldEffect::camera_shift)) {
    const double size = d.uniform(1, 5), angle = d.uniform(0, 2 * std::numbers::pi);
    w.camera_shift.shift_px = {size * std::cos(angle), size * std::sin(angle)};
    const double which = d.uniform(0, 1);
    w.camera_shift.views = which < 0.6   ? CameraShiftOptions::Views::both
                           : which < 0.8 ? CameraShiftOptions::Views::left
                                         : CameraShiftOptions::Views::right;
    w.camera_shift.at_s = d.uniform(0, duration);
    w.camera_shift.ramp_s = d.chance(0.5) ? 0.0 : d.uniform(0.2, 2);
  }
  if (on(WorldEffect::damage)) {
    w.damage.fraction = d.uniform(0.01, 0.05);
    w.damage.seed = static_cast<unsigned>(d.integer(0, 1 << 30));
  }
  if (on(WorldEffect::light)) {
    w.light.flicker = d.uniform(0, 0.1);
    w.light.exposure_step = d.uniform(-0.3, 0.3);
    w.light.step_at_s = d.uniform(0, duration);
  }
  if (on(WorldEffect::drift)) {
    w.drift.expansion = d.uniform(-0.003, 0.003);
    w.drift.offset_mm = {d.uniform(-0.05, 0.05), d.uniform(-0.05, 0.05), d.uniform(-0.05, 0.05)};
    w.drift.time_s = d.logUniform(30, 600);
  }
  return w;
}

}  // namespace

RandomScenario randomScenario(unsigned seed, bool world_effects, std::optional<WorldEffect> only) {
  Draw d(seed);
  RandomScenario out;
  RandomConditions& c = out.conditions;
  Scenario& sc = out.scenario;
  c.seed = seed;
  sc.name = "random_" + std::to_string(seed);
  sc.description = "seeded random combined motion (sim/random_scenario.hpp)";
  sc.seed = seed;

  c.model = d.chance(0.5) ? ContactModelKind::foundation : ContactModelKind::halfspace;
  c.friction = d.uniform(0.5, 1.5);
  c.kinetic_ratio = c.model == ContactModelKind::foundation ? d.uniform(0.6, 0.9) : 1.0;
  c.thickness_mm = d.uniform(4, 10);
  c.foundation_length_mm = c.model == ContactModelKind::foundation ? d.uniform(0.4, 1.0) * c.thickness_mm : 0.0;
  c.marker_depth_mm = d.uniform(0.1, 0.6);
  c.markers = 9 + 2 * d.integer(0, 8);
  c.noise_grey = d.uniform(1, 6);
  c.blur_px = d.uniform(0, 1.2);
  c.fps = d.logUniform(15, 240);
  const double speed_mm_s = d.uniform(3, 15), rate_deg_s = d.uniform(10, 60);
  PadOptions& pad = sc.pad;
  pad.contact_model = c.model;
  pad.friction = c.friction;
  pad.kinetic_ratio = c.model == ContactModelKind::foundation ? c.kinetic_ratio : pad.kinetic_ratio;
  pad.foundation_length_mm = c.foundation_length_mm;
  pad.thickness_mm = c.thickness_mm;
  pad.pattern.marker_depth_mm = c.marker_depth_mm;
  pad.pattern.rows = pad.pattern.cols = c.markers;
  pad.pattern.square_mm = 19.2 / (c.markers - 1);
  sc.fps = c.fps;
  sc.image.noise_sigma = c.noise_grey;
  sc.image.blur_sigma = c.blur_px;

  IndenterTrack main;
  const double kind = d.uniform(0, 1);
  Limits lim{3.5, 15, 30, 0.4, 3.0, speed_mm_s, rate_deg_s};
  if (kind < 0.6) {
    c.indenter = "finger";
    const double scale = d.uniform(0.7, 1.3);
    main.geometry.semi_axes = Eigen::Vector3d(7, 9, 6) * scale;
  } else if (kind < 0.85) {
    c.indenter = "sphere";
    const double r = d.uniform(4, 10);
    main.geometry.shape = IndenterShape::sphere;
    main.geometry.semi_axes = {r, r, r};
  } else {
    c.indenter = "plate";
    main.geometry.shape = IndenterShape::plate;
    main.geometry.plate_width = main.geometry.plate_length = 20;
    lim = {0, 5, 8, 0.3, 1.0, speed_mm_s, rate_deg_s};
  }
  c.episodes = d.integer(1, 3);
  double t = 0;
  for (int e = 0; e < c.episodes; ++e) t = appendEpisode(d, lim, main, t + d.uniform(0.1, 0.3));
  measureSpeeds(main, c);
  sc.indenters.push_back(main);

  c.two_fingers = c.indenter != "plate" && d.chance(0.15);
  if (c.two_fingers) {
    const Keyframe& touch = main.keyframes[1];  // the first press
    IndenterTrack second;
    second.geometry.semi_axes = Eigen::Vector3d(6, 8, 5) * d.uniform(0.7, 1.0);
    const double side = d.chance(0.5) ? 1.0 : -1.0;
    Keyframe k;
    k.t = main.keyframes[0].t;
    k.x = std::clamp(touch.x + side * d.uniform(6, 7), -8.0, 8.0);
    k.y = touch.y + d.uniform(-1, 1);
    k.depth = -0.3;
    second.keyframes.push_back(k);
    k.t = touch.t;
    k.depth = 0.5 * touch.depth;
    second.keyframes.push_back(k);
    k.t = std::max(k.t + 0.2, main.keyframes[main.keyframes.size() / 2].t);
    if (d.chance(0.5)) k.x += side * d.uniform(0, 1.5);
    second.keyframes.push_back(k);
    k.t += 0.3;
    k.depth = -0.3;
    second.keyframes.push_back(k);
    sc.indenters.push_back(second);
  }
  c.world_effects = world_effects;
  if (world_effects) {
    Draw world(seed ^ 0x5A17E0u);  // its own stream: the draws above are the same with the flag off
    sc.world = drawWorldEffects(world, sc.duration(), only);
  }
  return out;
}

}  // namespace onetip::sim
