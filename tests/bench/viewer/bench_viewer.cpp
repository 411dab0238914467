// The viewer's drawing rate, headless (EGL; Mesa llvmpipe on machines without
// a GPU): one pressed frame of demo_touch drawn again and again at 1280x720,
// finished (glFinish), with and without reading the image back; and in a GLFW
// window, shown (swap buffers + events) every time, when a display is set
// (e.g. under xvfb-run; skipped otherwise).
#include <benchmark/benchmark.h>

#include <memory>

#include "gl/gl_api.hpp"
#include "gl/headless_context.hpp"
#include "gl/offscreen_target.hpp"
#include "sim/simulator.hpp"
#include "viewer/glfw_window.hpp"
#include "viewer/viewer_renderer.hpp"
#include "viewer/viewer_session.hpp"

namespace {
using namespace onetip;

// A frame in contact (demo_touch at t = 1.17 s: pressed 1.5 mm, sliding).
struct PressedFrame {
  viewer::ViewerFrame frame;
  StereoCalibration calib;
  PressedFrame() {
    viewer::ViewerOptions o;
    o.input = std::string("sim:") + ONETIP_SOURCE_DIR + "/samples/scenarios/demo_touch.yaml";
    o.frames = 36;
    o.headless = true;
    viewer::runViewer(o, [&](const cv::Mat&, const viewer::ViewerFrame& f) { frame = f; });
    frame.camera = frame.camera.clone();
    calib = sim::Simulator(sim::loadScenario(o.input.substr(4))).calibration();
  }
};

const PressedFrame& pressed() {
  static const PressedFrame p;
  return p;
}

void drawLoop(benchmark::State& state, bool read_back) {
  const PressedFrame& p = pressed();
  const cv::Size size(1280, 720);
  const gl::HeadlessContext context;
  const gl::HeadlessContext::Binding current(context);
  const gl::OffscreenTarget target(size, GL_RGBA8);
  target.bind();
  viewer::ViewerRenderer renderer(p.calib);
  for (auto _ : state) {
    renderer.draw(p.frame, size);
    if (read_back) benchmark::DoNotOptimize(gl::readFramebufferBgr(size).data);
    glFinish();
  }
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.SetLabel(gl::currentGlDescription());
}

void BM_ViewerDraw(benchmark::State& state) { drawLoop(state, false); }
void BM_ViewerDrawAndReadBack(benchmark::State& state) { drawLoop(state, true); }
void BM_ViewerDrawInWindow(benchmark::State& state) {
  if (!viewer::displayAvailable()) {
    state.SkipWithError("no display (run under xvfb-run for the window's rate)");
    return;
  }
  const PressedFrame& p = pressed();
  viewer::ViewerWindow window({1280, 720}, "onetip bench_viewer");
  viewer::ViewerRenderer renderer(p.calib);
  for (auto _ : state) {
    renderer.draw(p.frame, window.framebufferSize());
    window.present();
    glFinish();
  }
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.SetLabel(gl::currentGlDescription());
}

BENCHMARK(BM_ViewerDraw)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
BENCHMARK(BM_ViewerDrawAndReadBack)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
BENCHMARK(BM_ViewerDrawInWindow)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
