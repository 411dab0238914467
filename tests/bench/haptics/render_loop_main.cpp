// haptic_render_loop: the simulated 1 kHz haptic display loop, with the kNN
// queries in a worker thread (haptics/render_worker.hpp).
//
// Loop thread, each 1 ms tick at an absolute deadline D_k (clock_nanosleep,
// TIMER_ABSTIME): every 10th tick hand the newest sensed vector (the BioTac-like
// sensor in the six remote interactions, 100 Hz) to the worker without waiting;
// fetch the worker's newest result, if any (lock-free); ramp the servo command
// towards it (command_ramp.hpp); select that configuration's vibration filter
// from the table (vibration_table.hpp, 15-deg grid, identified at start) and
// filter the 2.2 AC samples (2200 Hz) of this tick. The worker renders with
// n = 8 on the 166,375-row 3-deg dataset.
// The loop is haptics::PeriodicLoop (periodic_loop.hpp): ticks at absolute
// deadlines 1 ms apart, misses counted as it defines them, with the best
// scheduling policy the process may use (SCHED_FIFO, else nice -20, else
// normal) unless `normal` is given.
// The scheduler alone: before the loop, a null loop (same sleeps, no work) for
// `null_seconds` measures the wake-up latency (wake - D_k) and how often it
// exceeds the 1 ms period, so its share of the misses can be told apart.
// usage: haptic_render_loop [seconds=60] [out.csv] [null_seconds=30] [best|normal]
//   best (default) also locks memory (mlockall). The worker keeps the normal
//   policy. out.csv rows `what,value`.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/csv_table.hpp"
#include "haptics/biotac_like_sensor.hpp"
#include "haptics/command_ramp.hpp"
#include "haptics/display_grid.hpp"
#include "haptics/periodic_loop.hpp"
#include "haptics/remote_interactions.hpp"
#include "haptics/render_worker.hpp"
#include "haptics/vibration_channel.hpp"

using namespace onetip;
using namespace onetip::haptics;

namespace {

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(p * static_cast<double>(v.size())))];
}

}  // namespace

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::stod(argv[1]) : 60.0;
  const double null_seconds = argc > 3 ? std::stod(argv[3]) : 30.0;
  const bool best_policy = !(argc > 4 && std::string(argv[4]) == "normal");

  const PlatformKinematics device;
  const TactileDataset dataset = simulateDataset(device, BiotacLikeSensor(), 3.0);
  const KnnRenderer renderer(dataset);
  const VibrationTable table = VibrationTable::identify(simulatedSweepRecorder(device));
  BiotacLikeOptions o;
  o.noise_counts = 2.0;
  const BiotacLikeSensor sensor(o);
  std::vector<std::vector<double>> sensed;
  for (RemoteInteraction i : kRemoteInteractions)
    for (const ContactPlane& p : remoteInteraction(i)) sensed.push_back(sensor.sense(p));

  RenderWorker worker(renderer, 8, &table);  // its own thread keeps the normal policy
  PeriodicLoopOptions loop_options;
  loop_options.priority = best_policy ? LoopPriority::best_available : LoopPriority::normal;
  loop_options.lock_memory = best_policy;
  loop_options.record_timings = true;
  PeriodicLoop periodic(loop_options);

  const PeriodicLoopResult idle = periodic.run(std::lround(null_seconds * 1000.0), [](long) {});

  const std::array<double, 3> rest = {kServoMinDeg, kServoMinDeg, kServoMinDeg};
  CommandRamp ramp(rest, 10);
  VibrationChannel vibration(table.lookup(rest));
  std::vector<double> query_us;
  query_us.reserve(static_cast<size_t>(seconds * 100.0) + 16);
  double ac_phase = 0.0, ac_clock = 0.0, sink = 0.0;
  RenderedCommand latest;
  const PeriodicLoopResult loop = periodic.run(std::lround(seconds * 1000.0), [&](long k) {
    if (k % 10 == 0) worker.submit(sensed[static_cast<size_t>(k / 10) % sensed.size()].data());
    if (worker.latest(latest)) {
      ramp.target(latest.command);
      if (latest.vibration) vibration.select(*latest.vibration);
      query_us.push_back(latest.query_us);
    }
    sink += ramp.step()[0];
    for (ac_clock += kVibrationRateHz / 1000.0; ac_clock >= 1.0; ac_clock -= 1.0) {
      ac_phase += 2.0 * M_PI * 180.0 / kVibrationRateHz;
      sink += vibration.process(std::sin(ac_phase));
    }
  });

  const double pct = loop.missedPercent(), idle_pct = idle.missedPercent();
  std::printf("policy %s\n", toString(loop.policy).c_str());
  std::printf("null loop %.0f s: wake latency p50 %.1f us p99 %.1f us p99.9 %.1f us max %.1f us; missed %ld/%ld (%.3f%%)\n",
              null_seconds, percentile(idle.wake_latency_us, 0.5), percentile(idle.wake_latency_us, 0.99),
              percentile(idle.wake_latency_us, 0.999), percentile(idle.wake_latency_us, 1.0), idle.missed,
              idle.deadlines, idle_pct);
  std::printf("render loop %.0f s: missed %ld/%ld (%.3f%%); wake latency p50 %.1f p99 %.1f p99.9 %.1f max %.1f us; "
              "work p50 %.2f p99 %.2f max %.1f us\n",
              seconds, loop.missed, loop.deadlines, pct, percentile(loop.wake_latency_us, 0.5),
              percentile(loop.wake_latency_us, 0.99), percentile(loop.wake_latency_us, 0.999),
              percentile(loop.wake_latency_us, 1.0), percentile(loop.work_us, 0.5), percentile(loop.work_us, 0.99),
              percentile(loop.work_us, 1.0));
  std::printf("worker: %zu results, query p50 %.1f us p99 %.1f us max %.1f us (wall) (checksum %g)\n",
              query_us.size(), percentile(query_us, 0.5), percentile(query_us, 0.99), percentile(query_us, 1.0), sink);
  if (argc > 2) {
    CsvWriter out(argv[2], {"what", "value"});
    auto row = [&](const std::string& what, double v) { out.row({what, formatNumber(v, 3)}); };
    row("realtime_policy", loop.policy == ObtainedPolicy::realtime_fifo ? 1 : 0);
    row("deadlines", static_cast<double>(loop.deadlines));
    row("missed", static_cast<double>(loop.missed));
    row("missed_percent", pct);
    row("wake_latency_p50_us", percentile(loop.wake_latency_us, 0.5));
    row("wake_latency_p99_us", percentile(loop.wake_latency_us, 0.99));
    row("wake_latency_p999_us", percentile(loop.wake_latency_us, 0.999));
    row("wake_latency_max_us", percentile(loop.wake_latency_us, 1.0));
    row("work_p50_us", percentile(loop.work_us, 0.5));
    row("work_p99_us", percentile(loop.work_us, 0.99));
    row("work_max_us", percentile(loop.work_us, 1.0));
    row("worker_results", static_cast<double>(query_us.size()));
    row("query_p50_us", percentile(query_us, 0.5));
    row("query_p99_us", percentile(query_us, 0.99));
    row("query_max_us", percentile(query_us, 1.0));
    row("null_deadlines", static_cast<double>(idle.deadlines));
    row("null_missed_percent", idle_pct);
    row("null_wake_latency_p50_us", percentile(idle.wake_latency_us, 0.5));
    row("null_wake_latency_p99_us", percentile(idle.wake_latency_us, 0.99));
    row("null_wake_latency_p999_us", percentile(idle.wake_latency_us, 0.999));
    row("null_wake_latency_max_us", percentile(idle.wake_latency_us, 1.0));
    out.commit();
  }
  return 0;
}
