// Vision front end speed on 1920x1080 simulated frames (a press to 3.5 mm,
// tests/data/scenarios/deep_press.yaml, 17x17 markers, sigma 2 noise), one core:
//   ours: detect on a 960x1080 view; track (local search) on a view; a whole
//   frame = split + track both views (local search), and split + full
//   detection + track both views;
//   OpenCV: cv::findChessboardCornersSB + cv::cornerSubPix on the same views
//   and frames, in the same run (what a user would pick instead).
// Before the benchmarks it prints how often SB fails (and how often our
// detectBoard does) on the press frames and on a synthetic sequence of growing
// deformation (local scale to 0.6x, rotation, shear); after them, the ratio of
// the median CPU times (SB / ours). Run with --benchmark_repetitions=5 for
// medians (tests/bench/run_all.sh does).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "sim/scenario.hpp"
#include "sim/simulator.hpp"
#include "synthetic_board.hpp"
#include "vision/grid_tracker.hpp"

using namespace onetip;
using namespace onetip::vision;

namespace {

struct Frames {
  StereoCalibration calib;
  MarkerPattern pattern;
  std::vector<cv::Mat> frame;  // whole 1920x1080 frames
};

const Frames& pressFrames() {
  static const Frames frames = [] {
    Frames f;
    sim::Simulator simulator(
        sim::loadScenario(std::string(ONETIP_SOURCE_DIR) + "/tests/data/scenarios/deep_press.yaml"));
    f.calib = simulator.calibration();
    f.pattern = simulator.pattern();
    for (int k = 0; !simulator.done(); ++k) {
      simulator.next();
      if (k % 3 == 0) f.frame.push_back(simulator.render());
    }
    return f;
  }();
  return frames;
}

bool openCvSb(const cv::Mat& view, const MarkerPattern& pattern, std::vector<cv::Point2f>& corners) {
  if (!cv::findChessboardCornersSB(view, cv::Size(pattern.cols, pattern.rows), corners)) return false;
  cv::cornerSubPix(view, corners, cv::Size(5, 5), cv::Size(-1, -1),
                   cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 30, 0.01));
  return true;
}

void BM_OursDetectView(benchmark::State& state) {
  const Frames& f = pressFrames();
  const CornerDetector detector;
  size_t k = 0, corners = 0, runs = 0;
  for (auto _ : state) {
    const StereoViews v = splitViews(f.frame[k++ % f.frame.size()], f.calib);
    corners += detector.detect(v.left.raw).size(), ++runs;
  }
  state.counters["corners"] = static_cast<double>(corners) / static_cast<double>(runs);
}

void BM_OursTrackView(benchmark::State& state) {
  const Frames& f = pressFrames();
  const CornerDetector detector;
  GridTracker tracker(f.pattern);
  tracker.initialize(splitViews(f.frame[0], f.calib).left, detector);
  size_t k = 1, found = 0, runs = 0;
  for (auto _ : state) {
    const StereoViews v = splitViews(f.frame[k++ % f.frame.size()], f.calib);
    found += static_cast<size_t>(tracker.track(v.left, detector).found), ++runs;
  }
  state.counters["markers"] = static_cast<double>(found) / static_cast<double>(runs);
}

// Split + both views; local search, or full detection then matching.
void frameBenchmark(benchmark::State& state, bool local) {
  const Frames& f = pressFrames();
  const CornerDetector detector;
  GridTracker left(f.pattern), right(f.pattern);
  const StereoViews rest = splitViews(f.frame[0], f.calib);
  left.initialize(rest.left, detector);
  right.initialize(rest.right, detector);
  size_t k = 1, found = 0, runs = 0;
  for (auto _ : state) {
    const StereoViews v = splitViews(f.frame[k++ % f.frame.size()], f.calib);
    if (local) {
      found += static_cast<size_t>(left.track(v.left, detector).found + right.track(v.right, detector).found);
    } else {
      found += static_cast<size_t>(left.track(detectInView(detector, v.left), v.left).found +
                                   right.track(detectInView(detector, v.right), v.right).found);
    }
    ++runs;
  }
  state.counters["markers"] = static_cast<double>(found) / static_cast<double>(runs);
}
void BM_OursFrameLocal(benchmark::State& state) { frameBenchmark(state, true); }
void BM_OursFrameFullDetect(benchmark::State& state) { frameBenchmark(state, false); }

// SB + cornerSubPix on the left view, or on both views of each frame.
void sbBenchmark(benchmark::State& state, bool both_views) {
  const Frames& f = pressFrames();
  size_t k = 0, failed = 0, runs = 0;
  std::vector<cv::Point2f> corners;
  for (auto _ : state) {
    const StereoViews v = splitViews(f.frame[k++ % f.frame.size()], f.calib);
    for (const ViewHalf* h : {&v.left, &v.right}) {
      if (h == &v.right && !both_views) break;
      failed += openCvSb(h->raw, f.pattern, corners) ? 0 : 1, ++runs;
    }
  }
  state.counters["fail_rate"] = static_cast<double>(failed) / static_cast<double>(runs);
}
void BM_OpenCvSbView(benchmark::State& state) { sbBenchmark(state, false); }
void BM_OpenCvSbFrame(benchmark::State& state) { sbBenchmark(state, true); }

BENCHMARK(BM_OursDetectView)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OursTrackView)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OursFrameLocal)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OursFrameFullDetect)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OpenCvSbView)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OpenCvSbFrame)->Unit(benchmark::kMillisecond);

// How often each method gives no board, on the press views and on views of
// growing synthetic deformation.
void printFailureRates() {
  const Frames& f = pressFrames();
  int sb_fail = 0, ours_fail = 0, views = 0;
  std::vector<cv::Point2f> corners;
  for (const cv::Mat& frame : f.frame) {
    const StereoViews v = splitViews(frame, f.calib);
    for (const ViewHalf* h : {&v.left, &v.right}) {
      ++views;
      sb_fail += openCvSb(h->raw, f.pattern, corners) ? 0 : 1;
      ours_fail += detectBoard(*h, f.pattern).found == f.pattern.count() ? 0 : 1;
    }
  }
  std::printf("press scenario, %d views: SB failed on %d, ours (single-image detectBoard) on %d\n", views, sb_fail,
              ours_fail);
  sb_fail = ours_fail = 0;
  constexpr int kSteps = 8;
  for (int k = 1; k <= kSteps; ++k) {
    testing::BoardWarp w;
    w.bulge = 0.667 * k / kSteps, w.rotation_deg = 12.0 * k / kSteps, w.shear = 0.15 * k / kSteps;
    testing::BoardLook look;
    look.blur_sigma = 1.0, look.noise_sigma = 2.0, look.light_ramp = 0.4, look.seed = static_cast<unsigned>(k);
    const cv::Mat img = testing::renderBoard(w, look, cv::Size(960, 1080));
    const bool sb = openCvSb(img, f.pattern, corners);
    const bool ours = detectBoard(img, f.pattern).found == f.pattern.count();
    sb_fail += sb ? 0 : 1, ours_fail += ours ? 0 : 1;
    std::printf("  deformation step %d (centre scale %.2fx): SB %s, ours %s\n", k, 1.0 / (1.0 + w.bulge),
                sb ? "ok" : "FAILED", ours ? "ok" : "FAILED");
  }
  std::printf("synthetic growing deformation, %d views: SB failed on %d, ours on %d\n", kSteps, sb_fail, ours_fail);
}

// Console output plus the SB / ours ratios of the median CPU times (the
// per-core cost; wall time on a shared machine also counts other processes).
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs) {
      const bool median = r.run_type == Run::RT_Aggregate && r.aggregate_name == "median";
      if (median || r.run_type == Run::RT_Iteration) time_[r.run_name.function_name] = r.GetAdjustedCPUTime();
    }
    ConsoleReporter::ReportRuns(runs);
  }
  void Finalize() override {
    ConsoleReporter::Finalize();
    const auto ratio = [&](const char* a, const char* b) {
      if (time_.count(a) && time_.count(b))
        std::printf("CPU time %s / %s = %.1f (%.3f ms vs %.3f ms)\n", a, b, time_[a] / time_[b], time_[a], time_[b]);
    };
    ratio("BM_OpenCvSbView", "BM_OursDetectView");
    ratio("BM_OpenCvSbView", "BM_OursTrackView");
    ratio("BM_OpenCvSbFrame", "BM_OursFrameLocal");
    ratio("BM_OpenCvSbFrame", "BM_OursFrameFullDetect");
  }

 private:
  std::map<std::string, double> time_;
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  printFailureRates();
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
