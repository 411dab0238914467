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
// A tick misses its deadline when its work ends after D_{k+1}; when the thread
// wakes after D_{k+1} the skipped ticks count as missed and the loop resumes at
// the current period (no burst of catch-up ticks).
// The scheduler alone: before the loop, a null loop (same sleeps, no work) for
// `null_seconds` measures the wake-up latency (wake - D_k) and how often it
// exceeds the 1 ms period, so its share of the misses can be told apart.
// The loop thread's timer slack is set to 1 ns (PR_SET_TIMERSLACK).
// usage: haptic_render_loop [seconds=60] [out.csv] [null_seconds=30] [rt]
//   rt: SCHED_FIFO priority 80 and mlockall for the loop thread (the worker
//   keeps the normal policy). out.csv rows `what,value`.
#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/csv_table.hpp"
#include "haptics/biotac_like_sensor.hpp"
#include "haptics/command_ramp.hpp"
#include "haptics/display_grid.hpp"
#include "haptics/remote_interactions.hpp"
#include "haptics/render_worker.hpp"
#include "haptics/vibration_channel.hpp"

using namespace onetip;
using namespace onetip::haptics;

namespace {

constexpr long kPeriodNs = 1000000;

long long nowNs() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<long long>(t.tv_sec) * 1000000000LL + t.tv_nsec;
}

void sleepUntil(long long ns) {
  const timespec t{static_cast<time_t>(ns / 1000000000LL), static_cast<long>(ns % 1000000000LL)};
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &t, nullptr) != 0) {
  }
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(p * static_cast<double>(v.size())))];
}

struct LoopStats {
  long deadlines = 0, missed = 0;
  std::vector<double> wake_latency_us, work_us;
};

// Runs `ticks` deadlines 1 ms apart; tick(k) is the work of tick k.
template <typename Tick>
LoopStats runLoop(long ticks, Tick&& tick) {
  LoopStats s;
  s.wake_latency_us.reserve(static_cast<size_t>(ticks));
  s.work_us.reserve(static_cast<size_t>(ticks));
  const long long start = nowNs() + 2 * kPeriodNs;
  for (long k = 0; k < ticks;) {
    const long long deadline = start + k * kPeriodNs;
    sleepUntil(deadline);
    const long long wake = nowNs();
    s.wake_latency_us.push_back(static_cast<double>(wake - deadline) * 1e-3);
    const long late_periods = static_cast<long>((wake - deadline) / kPeriodNs);
    if (late_periods > 0) {  // woke after D_{k+1}: those deadlines passed unserved
      const long skipped = std::min(late_periods, ticks - k);
      s.missed += skipped;
      s.deadlines += skipped;
      k += skipped;
      if (k >= ticks) break;
    }
    tick(k);
    const long long end = nowNs();
    s.work_us.push_back(static_cast<double>(end - wake) * 1e-3);
    ++s.deadlines;
    if (end > start + (k + 1) * kPeriodNs) ++s.missed;
    ++k;
  }
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::stod(argv[1]) : 60.0;
  const double null_seconds = argc > 3 ? std::stod(argv[3]) : 30.0;
  const bool realtime = argc > 4 && std::string(argv[4]) == "rt";

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

  RenderWorker worker(renderer, 8, &table);  // created first: keeps the normal policy
  prctl(PR_SET_TIMERSLACK, 1UL);  // the loop thread's sleeps end on time (default slack: 50 us)
  bool rt_ok = false;
  if (realtime) {
    sched_param param{};
    param.sched_priority = 80;
    rt_ok = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param) == 0 && mlockall(MCL_CURRENT | MCL_FUTURE) == 0;
    if (!rt_ok) std::fprintf(stderr, "SCHED_FIFO / mlockall refused; running with the normal policy\n");
  }

  const LoopStats idle = runLoop(std::lround(null_seconds * 1000.0), [](long) {});

  const std::array<double, 3> rest = {kServoMinDeg, kServoMinDeg, kServoMinDeg};
  CommandRamp ramp(rest, 10);
  VibrationChannel vibration(table.lookup(rest));
  std::vector<double> query_us;
  query_us.reserve(static_cast<size_t>(seconds * 100.0) + 16);
  double ac_phase = 0.0, ac_clock = 0.0, sink = 0.0;
  RenderedCommand latest;
  const LoopStats loop = runLoop(std::lround(seconds * 1000.0), [&](long k) {
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

  const double pct = 100.0 * static_cast<double>(loop.missed) / static_cast<double>(loop.deadlines);
  const double idle_pct = 100.0 * static_cast<double>(idle.missed) / static_cast<double>(std::max(1L, idle.deadlines));
  std::printf("policy %s\n", rt_ok ? "SCHED_FIFO 80" : "normal");
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
    row("realtime_policy", rt_ok ? 1 : 0);
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
