// haptics/periodic_loop.hpp — a fixed-rate loop on the calling thread, for
// haptic display updates (1 kHz by default).
//
// Tick k is due at D_k = t0 + k T (CLOCK_MONOTONIC, absolute sleeps, so no
// drift accumulates; t0 is two periods after run() starts). A tick misses when
// its work ends after D_{k+1}. A thread that wakes after D_{k+1} counts the
// deadlines it slept through as missed, does not run their ticks, and resumes
// at the current period (no burst of catch-up ticks).
//
// Scheduling. On a shared machine most misses are wake-up latency: the thread
// is runnable at D_k but another process holds the core. With
// priority = best_available, run() asks for SCHED_FIFO (realtime_priority),
// else a nice of -20 for this thread, else keeps the normal policy; the result
// says which it got. The thread's timer slack is set to 1 ns so sleeps end on
// time. The thread's policy, nice and slack are restored when run() returns.
// lock_memory calls mlockall (process-wide, not undone) so page faults cannot
// stall a tick.
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

namespace onetip::haptics {

enum class LoopPriority { normal, best_available };
enum class ObtainedPolicy { normal, nice_raised, realtime_fifo };
std::string toString(ObtainedPolicy policy);

struct PeriodicLoopOptions {
  double period_ms = 1.0;                        // T, 0.05 .. 1000
  LoopPriority priority = LoopPriority::best_available;
  int realtime_priority = 80;                    // SCHED_FIFO priority, 1 .. 99
  bool lock_memory = false;                      // mlockall(MCL_CURRENT | MCL_FUTURE)
  bool record_timings = false;                   // keep every tick's wake latency and work time (grows without
                                                 // bound when run() has no tick limit)
  void validate() const;                         // throws InputError naming the bad field
};

struct PeriodicLoopResult {
  ObtainedPolicy policy = ObtainedPolicy::normal;
  long deadlines = 0;  // ticks due (run or skipped)
  long missed = 0;     // ticks whose work ended late, plus skipped ticks
  double max_wake_latency_us = 0;
  double max_work_us = 0;
  std::vector<double> wake_latency_us;  // per run tick (wake - D_k), with record_timings
  std::vector<double> work_us;          // per run tick, with record_timings
  double missedPercent() const { return deadlines > 0 ? 100.0 * static_cast<double>(missed) / static_cast<double>(deadlines) : 0.0; }
};

class PeriodicLoop {
 public:
  explicit PeriodicLoop(const PeriodicLoopOptions& options = {});

  // Runs tick(k) for the deadlines k = 0 .. ticks - 1 (ticks < 0: until
  // stop()), on the calling thread.
  PeriodicLoopResult run(long ticks, const std::function<void(long k)>& tick);
  // Ends a running loop after its current tick; callable from any thread or from a tick.
  void stop() noexcept { stop_.store(true, std::memory_order_relaxed); }

 private:
  PeriodicLoopOptions options_;
  std::atomic<bool> stop_{false};
};

}  // namespace onetip::haptics
