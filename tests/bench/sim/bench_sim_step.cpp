// Simulator speed: one field-level step (contact model + 17x17 marker ground
// truth) and one image-level frame (step + render 1920x1080), on scenarios
// that exercise stick, partial slip and gross slip. Arguments select the
// scenario and the contact-lattice resolution (nodes per marker spacing).
// The contact model reuses its Cholesky factors while the contact set holds, so
// steps differ in cost: the counter worst_step_ms is the slowest single step
// (one whose contact set changed and needed a fresh factor).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>

#include "sim/scenario.hpp"
#include "sim/simulator.hpp"

using namespace onetip::sim;

namespace {
const char* kScenarioNames[] = {"press", "slide_x", "twist", "flat"};
// "press" is tests/data/scenarios/deep_press.yaml, the finger to 3.5 mm (the largest contact set a press makes);
// the others are the shipped scenarios of the same name.
const char* kScenarioFiles[] = {"tests/data/scenarios/deep_press.yaml", "samples/scenarios/slide_x.yaml",
                                "samples/scenarios/twist.yaml", "samples/scenarios/flat.yaml"};

Scenario scenarioFor(int which, int nodes_per_square) {
  Scenario sc = loadScenario(std::string(ONETIP_SOURCE_DIR) + "/" + kScenarioFiles[which]);
  sc.pad.nodes_per_square = nodes_per_square;
  return sc;
}

void BM_FieldStep(benchmark::State& state) {
  const Scenario sc = scenarioFor(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  state.SetLabel(std::string(kScenarioNames[state.range(0)]) + " nps=" + std::to_string(state.range(1)));
  std::unique_ptr<Simulator> sim;
  double worst_ms = 0;
  for (auto _ : state) {
    if (!sim || sim->done()) {
      state.PauseTiming();
      sim = std::make_unique<Simulator>(sc);
      state.ResumeTiming();
    }
    const auto start = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(sim->next().input);
    worst_ms = std::max(worst_ms, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  state.counters["worst_step_ms"] = worst_ms;
}
BENCHMARK(BM_FieldStep)
    ->ArgsProduct({{0, 1, 2, 3}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

void BM_ImageFrame(benchmark::State& state) {
  const Scenario sc = scenarioFor(static_cast<int>(state.range(0)), 1);
  state.SetLabel(kScenarioNames[state.range(0)]);
  SimulatorOptions o;
  o.frames = 40;
  std::unique_ptr<Simulator> sim;
  for (auto _ : state) {
    if (!sim || sim->done()) {
      state.PauseTiming();
      sim = std::make_unique<Simulator>(sc, o);
      for (int k = 0; k < 15; ++k) sim->next();  // start in contact
      state.ResumeTiming();
    }
    sim->next();
    benchmark::DoNotOptimize(sim->render().data);
  }
}
BENCHMARK(BM_ImageFrame)->DenseRange(0, 3)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
}  // namespace

BENCHMARK_MAIN();
