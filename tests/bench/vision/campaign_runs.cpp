#include "campaign_runs.hpp"

#include <array>
#include <cmath>

#include "sim/random_scenario.hpp"

namespace onetip::bench {
namespace {

constexpr double kPadExtentMm = 19.2;
constexpr std::array<int, 5> kDensities{9, 13, 17, 21, 25};

sim::Scenario baseScenario(const std::string& name, int run_index) {
  sim::Scenario s;
  s.name = name;
  s.fps = 30;
  s.seed = static_cast<unsigned>(1000 + run_index);
  const int n = kDensities[static_cast<size_t>(run_index) % kDensities.size()];
  s.pad.pattern = MarkerPattern{n, n, kPadExtentMm / (n - 1)};
  s.image.noise_sigma = 1.0 + (run_index * 7 % 6);          // 1..6 grey levels
  s.image.blur_sigma = 0.4 * ((run_index * 5 / 3) % 4);     // 0, 0.4, 0.8, 1.2 px
  s.image.layout_seed = static_cast<std::uint64_t>(run_index);
  return s;
}

// Appends a keyframe `frames` frames after the last one, changed by `f`.
template <typename F>
void after(sim::IndenterTrack& track, double fps, double frames, F&& f) {
  sim::Keyframe k = track.keyframes.back();
  k.t += frames / fps;
  f(k);
  track.keyframes.push_back(k);
}

sim::IndenterTrack pressed(double fps, double depth) {
  sim::IndenterTrack track;
  track.keyframes.push_back(sim::Keyframe{0.0, 0, 0, -0.3, 0, 0, 0});
  after(track, fps, 8, [&](sim::Keyframe& k) { k.depth = depth; });
  after(track, fps, 2, [](sim::Keyframe&) {});
  return track;
}

}  // namespace

// Press 1 mm; slide +-4 squares along x (or y) at `speed` squares per frame, reversing twice.
CampaignRun slideRun(int index, double speed, bool along_y) {
  CampaignRun run{"slide", speed, baseScenario("slide", index)};
  sim::Scenario& s = run.scenario;
  const double sq = s.pad.pattern.square_mm, span = 4 * sq, frames = std::ceil(4 / speed);
  sim::IndenterTrack t = pressed(s.fps, 1.0);
  const auto move = [&](double to, double legs) {
    after(t, s.fps, legs * frames, [&](sim::Keyframe& k) { (along_y ? k.y : k.x) = to; });
  };
  move(span, 1);
  move(-span, 2);
  move(0, 1);
  after(t, s.fps, 3, [](sim::Keyframe&) {});
  s.indenters.push_back(t);
  return run;
}

// Heavy shear: 2 mm press at friction 2, slide 3 squares and straight back.
CampaignRun shearRun(int index, double speed) {
  CampaignRun run{"shear", speed, baseScenario("shear", index)};
  sim::Scenario& s = run.scenario;
  s.pad.friction = 2.0;
  const double sq = s.pad.pattern.square_mm, frames = std::ceil(std::hypot(3, 1) / speed);
  sim::IndenterTrack t = pressed(s.fps, 2.0);
  after(t, s.fps, frames, [&](sim::Keyframe& k) { k.x = 3 * sq, k.y = 1 * sq; });
  after(t, s.fps, frames, [&](sim::Keyframe& k) { k.x = 0, k.y = 0; });
  after(t, s.fps, 3, [](sim::Keyframe&) {});
  s.indenters.push_back(t);
  return run;
}

namespace {

// Steep tilts: roll and pitch to +-35 degrees and back; `speed` scales the rate.
CampaignRun tilt(int index, double speed) {
  CampaignRun run{"tilt", speed, baseScenario("tilt", index)};
  sim::Scenario& s = run.scenario;
  const double frames = std::ceil(2 / speed);
  sim::IndenterTrack t = pressed(s.fps, 1.5);
  after(t, s.fps, frames, [](sim::Keyframe& k) { k.roll = 35; });
  after(t, s.fps, 2 * frames, [](sim::Keyframe& k) { k.roll = -35; });
  after(t, s.fps, frames, [](sim::Keyframe& k) { k.roll = 0, k.pitch = 30; });
  after(t, s.fps, 2 * frames, [](sim::Keyframe& k) { k.pitch = -30; });
  after(t, s.fps, frames, [](sim::Keyframe& k) { k.pitch = 0; });
  s.indenters.push_back(t);
  return run;
}

// Combined: press deeper while sliding, twisting and tilting, then back.
CampaignRun combined(int index, double speed) {
  CampaignRun run{"combined", speed, baseScenario("combined", index)};
  sim::Scenario& s = run.scenario;
  const double sq = s.pad.pattern.square_mm, frames = std::ceil(2.5 / speed);  // 2.5 squares per leg
  sim::IndenterTrack t = pressed(s.fps, 1.0);
  after(t, s.fps, frames, [&](sim::Keyframe& k) { k.x = 2 * sq, k.y = -1.5 * sq, k.depth = 1.8, k.yaw = 15, k.roll = 25; });
  after(t, s.fps, 2 * frames, [&](sim::Keyframe& k) { k.x = -2 * sq, k.y = 1.5 * sq, k.yaw = -15, k.roll = 0, k.pitch = -25; });
  after(t, s.fps, frames, [&](sim::Keyframe& k) { k.x = 0, k.y = 0, k.depth = 1.0, k.yaw = 0, k.pitch = 0; });
  s.indenters.push_back(t);
  return run;
}

}  // namespace

std::vector<CampaignRun> scriptedRuns() {
  std::vector<CampaignRun> runs;
  int index = 0;
  for (double speed : {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0}) {
    runs.push_back(slideRun(index++, speed, false));
    runs.push_back(slideRun(index++, speed, true));
    runs.push_back(shearRun(index++, speed));
    runs.push_back(combined(index++, speed));
  }
  for (double speed : {0.25, 0.5, 1.0}) runs.push_back(tilt(index++, speed));
  return runs;
}

std::vector<CampaignRun> randomRuns(int count, int max_frames) {
  std::vector<CampaignRun> runs;
  for (int seed = 1; seed <= count; ++seed) runs.push_back({"random", 0.0, sim::randomScenario(static_cast<unsigned>(seed)).scenario, max_frames});
  return runs;
}

}  // namespace onetip::bench
