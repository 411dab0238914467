// Per-frame cost of contact analysis and the pose solve on recorded simulator
// frames (slide_x at the default noise, 17 x 17 markers), per solver policy
// and per accumulation; the one frame in which a recovery measures a creeping
// gel (input/gel_creep.hpp); and the surface normals: grid neighbours vs PCL's
// NormalEstimation (k nearest neighbours), with their angular error against
// the exact normal of a smooth spherical dimple as a counter.
#include <benchmark/benchmark.h>
#include <pcl/features/normal_3d.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cmath>
#include <random>
#include <string>

#include "contact/contact_analyzer.hpp"
#include "contact/surface_normals.hpp"
#include "input/gel_creep.hpp"
#include "pose/adaptive_pose_estimator.hpp"
#include "sim_replay.hpp"

using namespace onetip;

namespace {

const poseval::Recording& slideRecording() {
  static const poseval::Recording r = poseval::record(poseval::sampleScenario("slide_x"));
  return r;
}

// Frames of the recording in contact, in order (the estimator keeps state).
std::vector<size_t> contactFrames(const poseval::Recording& r) {
  std::vector<size_t> ids;
  for (size_t k = 0; k < r.frames.size(); ++k)
    if (r.truth[k].in_contact) ids.push_back(k);
  return ids;
}

void BM_ContactAnalysis(benchmark::State& state) {
  const auto& rec = slideRecording();
  const auto ids = contactFrames(rec);
  const contact::ContactAnalyzer analyzer;
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(analyzer.analyze(rec.frames[ids[i]], rec.rest));
    i = (i + 1) % ids.size();
  }
}
BENCHMARK(BM_ContactAnalysis);

void BM_ContactAndPose(benchmark::State& state) {
  const auto& rec = slideRecording();
  const auto ids = contactFrames(rec);
  pose::AdaptivePoseOptions o;
  o.policy = static_cast<pose::ModelPolicy>(state.range(0));
  const contact::ContactAnalyzer analyzer;
  pose::AdaptivePoseEstimator estimator(o);
  size_t i = 0;
  for (auto _ : state) {
    if (i == 0) estimator.reset();  // replay the contact from its onset
    const auto field = analyzer.analyze(rec.frames[ids[i]], rec.rest);
    benchmark::DoNotOptimize(estimator.update(field, rec.frames[ids[i]], pose::SensorSelf{}));
    i = (i + 1) % ids.size();
  }
  state.SetLabel(std::string(o.policy == pose::ModelPolicy::adaptive          ? "adaptive"
                             : o.policy == pose::ModelPolicy::kabsch_only     ? "kabsch_only"
                             : o.policy == pose::ModelPolicy::stick_slip_only ? "ceres_every_frame"
                             : o.policy == pose::ModelPolicy::centroid_only   ? "centroid_only"
                                                                              : "weighted"));
}
BENCHMARK(BM_ContactAndPose)->DenseRange(0, 4);

void BM_Tracker(benchmark::State& state) {
  const auto& rec = slideRecording();
  input::PoseTrackerOptions o;
  o.accumulation = static_cast<input::Accumulation>(state.range(0));
  o.filter.kind = input::FilterKind::moving_average;
  input::PoseTracker tracker(o);
  size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(tracker.update(rec.frames[k], rec.rest, rec.truth[k].t));
    k = (k + 1) % rec.frames.size();
  }
  state.SetLabel(o.accumulation == input::Accumulation::composed ? "composed" : "euler_sum");
}
BENCHMARK(BM_Tracker)->DenseRange(0, 1);

// The frame that ends the recovery after creep_unheld's first lift-off (the second press's first frame): the
// gel's constants are fitted to every frame recorded since the first contact began (the golden section inverts
// them all per trial gain). The contact flags are the truth's; the frames before it are fed outside the timing.
void BM_GelFromRecovery(benchmark::State& state) {
  static const poseval::Recording rec = poseval::record(
      sim::loadScenario(std::string(ONETIP_SOURCE_DIR) + "/tests/data/scenarios/world/creep_unheld.yaml"));
  constexpr double kNoiseMm = 0.0006;  // sim_replay.hpp's marker noise per axis
  input::GelCreep primed;
  size_t k = 0;
  for (; k < rec.frames.size(); ++k) {
    input::GelCreep trial = primed;
    if (trial.observe(rec.frames[k], rec.rest, rec.truth[k].t, rec.truth[k].in_contact, kNoiseMm, {})) break;
    primed = trial;
  }
  if (k == rec.frames.size()) {
    state.SkipWithError("creep_unheld's recovery measured no gel");
    return;
  }
  for (auto _ : state) {
    state.PauseTiming();
    input::GelCreep gel = primed;
    state.ResumeTiming();
    benchmark::DoNotOptimize(gel.observe(rec.frames[k], rec.rest, rec.truth[k].t, rec.truth[k].in_contact,
                                         kNoiseMm, {}));
  }
  state.counters["recorded_frames"] = static_cast<double>(k);
  state.counters["markers"] = static_cast<double>(rec.rest.position.size());
}
BENCHMARK(BM_GelFromRecovery)->Unit(benchmark::kMillisecond);

// A 17 x 17 marker layer shaped as a sphere of radius 20 mm (1 mm deep at the
// centre), with a pessimistic noise of 0.012 mm per axis (20x the front end's).
struct Dimple {
  MarkerField field{17, 17};
  std::vector<Eigen::Vector3d> truth;
  Dimple() {
    std::mt19937 rng(1);
    std::normal_distribution<double> noise(0, 0.012);
    for (int r = 0; r < 17; ++r)
      for (int c = 0; c < 17; ++c) {
        const double x = (c - 8) * 1.2, y = (r - 8) * 1.2;
        const Eigen::Vector3d p(x, y, 19.0 - std::sqrt(400 - x * x - y * y));
        truth.push_back((Eigen::Vector3d(0, 0, 19) - p).normalized());
        field.set(r * 17 + c, p + Eigen::Vector3d(noise(rng), noise(rng), noise(rng)));
      }
  }
  double meanErrorDeg(const std::vector<Eigen::Vector3d>& n) const {
    double sum = 0;
    for (size_t i = 0; i < n.size(); ++i) sum += std::acos(std::min(1.0, std::abs(n[i].dot(truth[i]))));
    return sum / static_cast<double>(n.size()) * 57.29577951308232;
  }
};

void BM_NormalsGrid(benchmark::State& state) {
  const Dimple d;
  std::vector<Eigen::Vector3d> n;
  std::vector<std::uint8_t> ok;
  for (auto _ : state) contact::gridSurfaceNormals(d.field, n, ok);
  state.counters["mean_error_deg"] = d.meanErrorDeg(n);
}
BENCHMARK(BM_NormalsGrid);

void BM_NormalsPcl(benchmark::State& state) {
  const Dimple d;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& p : d.field.position)
    cloud->push_back(pcl::PointXYZ(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())));
  pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> ne;
  ne.setInputCloud(cloud);
  ne.setKSearch(static_cast<int>(state.range(0)));
  pcl::PointCloud<pcl::Normal> normals;
  for (auto _ : state) ne.compute(normals);
  std::vector<Eigen::Vector3d> n;
  for (const auto& q : normals) n.emplace_back(q.normal_x, q.normal_y, q.normal_z);
  state.counters["mean_error_deg"] = d.meanErrorDeg(n);
}
BENCHMARK(BM_NormalsPcl)->Arg(9)->Arg(25);

}  // namespace

BENCHMARK_MAIN();
