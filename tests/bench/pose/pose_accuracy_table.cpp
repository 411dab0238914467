// Writes the accuracy tables behind docs/pose/*.png (run from the repository
// root or pass the output folder):
//   solvers.csv  policy,accumulation,ms_per_frame,trans_rmse_mm,rot_rmse_deg
//   density.csv  markers,ms_per_frame,trans_rmse_mm,rot_rmse_deg
//   noise.csv    noise_mm,trans_rmse_mm,rot_rmse_deg,slip_f1
// Translation RMSE: mean over dx, dy, dz of a press to 3.5 mm
// (tests/data/scenarios/deep_press.yaml, the deepest press the working range
// leaves frames of), slide_x and sweep_y within the paper's range; rotation RMSE: the driven axis of twist, pitch, roll at 0.5 mm
// depth within the working range. Time: median wall time per frame of contact
// analysis + pose (one thread) over those replays. Default noise 0.0006 mm
// per axis (the rendered front end's error); in the noise sweep the estimator
// measures the noise itself on the frames before contact, its prior set to the
// sweep's sigma.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/csv_table.hpp"
#include "replay_metrics.hpp"
#include "sim/scenario.hpp"

using namespace onetip;
using namespace onetip::poseval;

namespace {

struct Score {
  double ms = 0, trans = 0, rot = 0, f1 = 0;
};

const char* kTranslation[] = {"press", "slide_x", "sweep_y"};
const char* kRotation[] = {"twist", "pitch", "roll"};

// The shipped scenario of that name; "press" is the press to 3.5 mm.
sim::Scenario tableScenario(const std::string& name) {
  if (name == "press")
    return sim::loadScenario(std::string(ONETIP_SOURCE_DIR) + "/tests/data/scenarios/deep_press.yaml");
  return sampleScenario(name);
}

sim::Scenario withPad(const std::string& name, int markers) {
  sim::Scenario sc = tableScenario(name);
  sc.pad.pattern.rows = sc.pad.pattern.cols = markers;
  sc.pad.pattern.square_mm = 19.2 / (markers - 1);  // same pad extent as 17 x 17 at 1.2 mm
  return sc;
}

Score evaluate(const std::function<sim::Scenario(const std::string&)>& scenario, const ReplayOptions& o,
               input::Accumulation acc) {
  Score s;
  std::vector<double> ms;
  auto timed = [&](const Recording& rec) {
    input::PoseTracker tracker(o.tracker);
    for (size_t k = 0; k < rec.frames.size(); ++k) {
      const auto t0 = std::chrono::steady_clock::now();
      const auto r = tracker.update(rec.frames[k], rec.rest, rec.truth[k].t);
      const auto t1 = std::chrono::steady_clock::now();
      if (r.contact) ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    }
  };
  const EstimateOf est = acc == input::Accumulation::composed ? EstimateOf(composedOf) : EstimateOf(eulerSumOf);
  for (const char* name : kTranslation) {
    const Recording rec = record(scenario(name), o);
    timed(rec);
    const auto r = axisRmse(track(rec, o.tracker), est, [](const ReplayFrame& f) {
      return std::abs(f.gt.dx) <= 1.5 && std::abs(f.gt.dy) <= 1.5 && f.gt.dz >= 0 && f.gt.dz <= 3;
    });
    s.trans += (r.rmse[0] + r.rmse[1] + r.rmse[2]) / 9.0;
  }
  for (size_t i = 0; i < 3; ++i) {
    const Recording rec = record(scenario(kRotation[i]), o);
    timed(rec);
    const auto r = axisRmse(track(rec, o.tracker), est, [](const ReplayFrame& f) {
      return std::abs(f.gt.yaw) <= 15 && std::abs(f.gt.pitch) <= 40 && std::abs(f.gt.roll) <= 40;
    });
    s.rot += r.rmse[3 + i] / 3.0;
  }
  std::vector<ReplayFrame> slides;
  for (const char* name : {"slide_x", "slide_y"}) {
    const auto f = track(record(scenario(name), o), o.tracker);
    slides.insert(slides.end(), f.begin(), f.end());
  }
  s.f1 = slipF1(slides).f1;
  std::nth_element(ms.begin(), ms.begin() + static_cast<long>(ms.size() / 2), ms.end());
  s.ms = ms[ms.size() / 2];
  return s;
}

std::string num(double v) { return formatNumber(v, 5); }

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : "docs/pose/data";
  const auto sample = [](const std::string& n) { return tableScenario(n); };

  CsvWriter solvers(dir + "/solvers.csv", {"policy", "accumulation", "ms_per_frame", "trans_rmse_mm", "rot_rmse_deg"});
  const std::pair<pose::ModelPolicy, const char*> policies[] = {{pose::ModelPolicy::adaptive, "adaptive"},
                                                                {pose::ModelPolicy::kabsch_only, "kabsch_eq1"},
                                                                {pose::ModelPolicy::stick_slip_only, "ceres_eq13"},
                                                                {pose::ModelPolicy::centroid_only, "centroid"}};
  for (const auto& [policy, name] : policies)
    for (auto acc : {input::Accumulation::composed, input::Accumulation::euler_sum}) {
      ReplayOptions o;
      o.tracker.pose.policy = policy;
      o.tracker.accumulation = acc;
      const Score s = evaluate(sample, o, acc);
      const char* acc_name = acc == input::Accumulation::composed ? "composed" : "euler_sum";
      std::printf("%-10s %-9s %.3f ms  trans %.4f mm  rot %.3f deg\n", name, acc_name, s.ms, s.trans, s.rot);
      solvers.row({name, acc_name, num(s.ms), num(s.trans), num(s.rot)});
    }
  solvers.commit();

  CsvWriter density(dir + "/density.csv", {"markers", "ms_per_frame", "trans_rmse_mm", "rot_rmse_deg"});
  for (int n : {9, 13, 17, 25}) {
    const Score s = evaluate([n](const std::string& name) { return withPad(name, n); }, ReplayOptions{},
                             input::Accumulation::composed);
    std::printf("%2dx%-2d %.3f ms  trans %.4f mm  rot %.3f deg\n", n, n, s.ms, s.trans, s.rot);
    density.row({std::to_string(n), num(s.ms), num(s.trans), num(s.rot)});
  }
  density.commit();

  CsvWriter noise(dir + "/noise.csv", {"noise_mm", "trans_rmse_mm", "rot_rmse_deg", "slip_f1"});
  for (double sigma : {0.0, 0.0003, 0.0006, 0.0012, 0.003, 0.006, 0.012}) {
    ReplayOptions o;
    o.noise_mm = sigma;
    // The estimator is told the front end's noise: above the default 0.0006 mm
    // its noise-driven thresholds grow in proportion.
    o.tracker.pose.self.prior_noise_mm = std::max(sigma, 1e-5);
    const Score s = evaluate(sample, o, input::Accumulation::composed);
    std::printf("noise %.3f  trans %.4f mm  rot %.3f deg  F1 %.3f\n", sigma, s.trans, s.rot, s.f1);
    noise.row({num(sigma), num(s.trans), num(s.rot), num(s.f1)});
  }
  noise.commit();
  return 0;
}
