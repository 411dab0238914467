// Image-level simulator speed: one 1920x1080 frame of the pad (175 x 175
// vertex lattice, 0.15 mm spacing) at rest and deformed, without and with
// the image effects, by the CPU rasteriser and (if built) the GLSL renderer
// on headless EGL. "1thread" pins OpenCV to one thread (the CPU renderer
// otherwise draws the two views concurrently); the GLSL renderer's llvmpipe
// uses LP_NUM_THREADS threads (default: all cores). CPU times are of the
// whole process (all threads).
#include <benchmark/benchmark.h>

#include <opencv2/core/utility.hpp>

#include "render_test_sheets.hpp"
#include "sim/renderer.hpp"
#ifdef ONETIP_HAVE_GLSL_RENDERER
#include <memory>

#include "sim/glsl_renderer.hpp"
#endif

namespace {

using namespace onetip::sim;

ImageEffects fullEffects() {
  ImageEffects e;
  e.noise_sigma = 2;
  e.blur_sigma = 1.0;
  e.vignetting = 0.3;
  e.exposure = 1.1;
  e.light_gradient = 0.2;
  e.dust_blobs = 5;
  e.specular_spots = 3;
  e.occlusion_fraction = 0.1;
  return e;
}

std::vector<CheckerSheet> padSheets(bool deformed) {
  return {testsupport::padSheet(deformed ? testsupport::deformedPoint : testsupport::restPoint)};
}

template <typename Renderer>
void renderLoop(benchmark::State& state, const Renderer& renderer, bool deformed, bool effects) {
  const std::vector<CheckerSheet> sheets = padSheets(deformed);
  const ImageEffects e = effects ? fullEffects() : testsupport::noEffects();
  std::uint64_t seed = 0;
  for (auto _ : state) benchmark::DoNotOptimize(renderer.render(sheets, e, seed++));
  state.counters["vertices"] = static_cast<double>(sheets[0].position.size());
}

void cpuFrame(benchmark::State& state, bool deformed, bool effects, int threads) {
  const int previous = cv::getNumThreads();
  cv::setNumThreads(threads);
  renderLoop(state, FrameRenderer(CameraRig::fromOptions({})), deformed, effects);
  cv::setNumThreads(previous);
}

#ifdef ONETIP_HAVE_GLSL_RENDERER
void glslFrame(benchmark::State& state, bool deformed, bool effects) {
  static const std::unique_ptr<GlslFrameRenderer> renderer = [] {
    try {
      return std::make_unique<GlslFrameRenderer>(CameraRig::fromOptions({}));
    } catch (const std::runtime_error&) {
      return std::unique_ptr<GlslFrameRenderer>();
    }
  }();
  if (!renderer) {
    state.SkipWithError("no headless EGL / OpenGL 3.3 core context");
    return;
  }
  renderLoop(state, *renderer, deformed, effects);
}
#endif

void configure(benchmark::internal::Benchmark* b) {
  b->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime()->Repetitions(5)->ReportAggregatesOnly(true);
}

std::string caseName(const char* renderer, bool deformed, bool effects) {
  return std::string("render_1920x1080/") + renderer + (deformed ? "/deformed" : "/flat") +
         (effects ? "/effects" : "/clean");
}

void registerAll() {
  for (const bool deformed : {false, true})
    for (const bool effects : {false, true}) {
      for (const int threads : {1, 2})
        configure(benchmark::RegisterBenchmark((caseName("cpu", deformed, effects) + "/" + std::to_string(threads) +
                                                "thread").c_str(),
                                               cpuFrame, deformed, effects, threads));
#ifdef ONETIP_HAVE_GLSL_RENDERER
      configure(benchmark::RegisterBenchmark(caseName("glsl", deformed, effects).c_str(), glslFrame, deformed, effects));
#endif
    }
}

}  // namespace

int main(int argc, char** argv) {
  registerAll();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
