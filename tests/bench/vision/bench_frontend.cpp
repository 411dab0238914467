// The whole vision front end per frame (split, detect, track, triangulate) on
// 1920x1080 simulated frames of a press to 3.5 mm (tests/data/scenarios/deep_press.yaml) at the default noise, one
// core; the same from MJPEG bytes (TurboJPEG decode straight to grey first);
// and, in the same run, what a user would pick instead: OpenCV's
// findChessboardCornersSB or findChessboardCorners + cornerSubPix on both views.
// Counters: front_end_ms (detect + track + triangulate, the processor's own
// stage clocks) and process_ms (including contact and pose). BM_ViewShiftCheck
// times what the processor adds on a frame out of contact to tell a moved
// mirror or camera (vision/view_shift.hpp): the decision and the corrected
// copies of both views, on this recording's 2-D markers.
#include <benchmark/benchmark.h>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "capture/jpeg_grey_decoder.hpp"
#include "pipeline/frame_processor.hpp"
#include "sim/simulator.hpp"
#include "vision/view_shift.hpp"
#include "vision/view_split.hpp"

using namespace onetip;

namespace {
struct Recording {
  StereoCalibration calib;
  MarkerPattern pattern;
  std::vector<cv::Mat> frames;                   // a press and release, continuous motion
  std::vector<std::vector<std::uint8_t>> jpegs;  // the same frames as MJPEG would carry them
};

const Recording& recording() {
  static const Recording rec = [] {
    Recording r;
    sim::SimulatorOptions o;
    o.frames = 48;
    sim::Simulator s(sim::loadScenario(std::string(ONETIP_SOURCE_DIR) + "/tests/data/scenarios/deep_press.yaml"), o);
    r.calib = s.calibration();
    r.pattern = s.pattern();
    while (!s.done()) {
      s.next();
      r.frames.push_back(s.render());
      std::vector<std::uint8_t> jpg;
      cv::imencode(".jpg", r.frames.back(), jpg, {cv::IMWRITE_JPEG_QUALITY, 90});
      r.jpegs.push_back(std::move(jpg));
    }
    return r;
  }();
  return rec;
}

// Frame index of step k in a ping-pong over the recording (motion stays continuous).
size_t pingPong(size_t k, size_t n) {
  const size_t period = 2 * (n - 1);
  const size_t p = k % period;
  return p < n ? p : period - p;
}

template <typename FrameAt>
void runFrontEnd(benchmark::State& state, FrameAt&& frame_at) {
  const Recording& rec = recording();
  pipeline::FrameProcessor processor(rec.calib, rec.pattern);
  processor.setReference(rec.frames.front());
  double front_end = 0, process = 0;
  size_t k = 1;
  for (auto _ : state) {
    const cv::Mat& frame = frame_at(pingPong(k++, rec.frames.size()));
    const pipeline::FrameResult r = processor.process(frame, 0.0);
    if (r.status != pipeline::FrameStatus::ok) state.SkipWithError(r.message.c_str());
    front_end += r.times.detect + r.times.track + r.times.triangulate;
    process += r.times.process;
  }
  state.counters["front_end_ms"] = benchmark::Counter(front_end / state.iterations());
  state.counters["process_ms"] = benchmark::Counter(process / state.iterations());
}

void BM_FrontEnd(benchmark::State& state) {
  const Recording& rec = recording();
  runFrontEnd(state, [&](size_t i) -> const cv::Mat& { return rec.frames[i]; });
}
BENCHMARK(BM_FrontEnd)->Unit(benchmark::kMillisecond);

void BM_FrontEndFromMjpeg(benchmark::State& state) {
  const Recording& rec = recording();
  capture::JpegGreyDecoder decoder;
  cv::Mat grey;
  runFrontEnd(state, [&](size_t i) -> const cv::Mat& {
    const auto& jpg = rec.jpegs[i];
    decoder.decode(jpg.data(), jpg.size(), {rec.calib.image_width, rec.calib.image_height}, grey);
    return grey;
  });
}
BENCHMARK(BM_FrontEndFromMjpeg)->Unit(benchmark::kMillisecond);

void BM_ViewShiftCheck(benchmark::State& state) {
  const Recording& rec = recording();
  pipeline::FrameProcessor processor(rec.calib, rec.pattern);
  processor.setReference(rec.frames.front());
  const vision::ViewMarkers rest_left = processor.leftViewMarkers(), rest_right = processor.rightViewMarkers();
  processor.process(rec.frames[1], 0.0);  // a frame at rest: its corners differ from the reference's by noise
  vision::ViewMarkers now_left = processor.leftViewMarkers(), now_right = processor.rightViewMarkers();
  vision::ViewShiftKeeper keeper(rec.calib.flip_left, rec.calib.flip_right);
  for (auto _ : state) {
    benchmark::DoNotOptimize(keeper.update(rest_left, rest_right, now_left, now_right));
    keeper.correct(now_left, now_right);
    benchmark::DoNotOptimize(now_left.point.data());
  }
}
BENCHMARK(BM_ViewShiftCheck)->Unit(benchmark::kMicrosecond);

// OpenCV's detector on both views of the same frames, then cornerSubPix.
template <typename Find>
void runOpenCv(benchmark::State& state, Find&& find) {
  const Recording& rec = recording();
  const cv::Size size(rec.pattern.cols, rec.pattern.rows);
  size_t k = 0;
  int64_t failures = 0, views = 0;
  for (auto _ : state) {
    const vision::StereoViews v = vision::splitViews(rec.frames[pingPong(k++, rec.frames.size())], rec.calib);
    for (const cv::Mat& half : {v.left.raw, v.right.raw}) {
      std::vector<cv::Point2f> corners;
      ++views;
      if (!find(half, size, corners)) {
        ++failures;
        continue;
      }
      cv::cornerSubPix(half, corners, {5, 5}, {-1, -1}, {cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 30, 0.01});
    }
  }
  state.counters["failed_views"] = benchmark::Counter(double(failures));
  state.counters["views"] = benchmark::Counter(double(views));
}

void BM_OpenCvChessboardSB(benchmark::State& state) {
  runOpenCv(state, [](const cv::Mat& half, cv::Size size, std::vector<cv::Point2f>& corners) {
    return cv::findChessboardCornersSB(half, size, corners);
  });
}
BENCHMARK(BM_OpenCvChessboardSB)->Unit(benchmark::kMillisecond)->Iterations(16);

// The classic detector (adaptive threshold, quad linking), default flags.
void BM_OpenCvChessboard(benchmark::State& state) {
  runOpenCv(state, [](const cv::Mat& half, cv::Size size, std::vector<cv::Point2f>& corners) {
    return cv::findChessboardCorners(half, size, corners);
  });
}
BENCHMARK(BM_OpenCvChessboard)->Unit(benchmark::kMillisecond)->Iterations(16);
}  // namespace

BENCHMARK_MAIN();
