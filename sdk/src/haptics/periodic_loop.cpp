#include "haptics/periodic_loop.hpp"

#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <limits>

#include "core/error.hpp"

namespace onetip::haptics {

namespace {

long long nowNs() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<long long>(t.tv_sec) * 1000000000LL + t.tv_nsec;
}

void sleepUntil(long long ns) {
  const timespec t{static_cast<time_t>(ns / 1000000000LL), static_cast<long>(ns % 1000000000LL)};
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &t, nullptr) == EINTR) {
  }
}

// The calling thread's scheduling state, raised for the loop and restored after it.
class ThreadScheduling {
 public:
  ThreadScheduling()
      : tid_(static_cast<id_t>(syscall(SYS_gettid))), slack_(prctl(PR_GET_TIMERSLACK, 0, 0, 0, 0)) {
    pthread_getschedparam(pthread_self(), &policy_, &param_);
    errno = 0;
    nice_ = getpriority(PRIO_PROCESS, tid_);
  }
  ~ThreadScheduling() {
    pthread_setschedparam(pthread_self(), policy_, &param_);
    setpriority(PRIO_PROCESS, tid_, nice_);
    if (slack_ > 0) prctl(PR_SET_TIMERSLACK, static_cast<unsigned long>(slack_), 0, 0, 0);
  }
  ThreadScheduling(const ThreadScheduling&) = delete;
  ThreadScheduling& operator=(const ThreadScheduling&) = delete;

  ObtainedPolicy raise(const PeriodicLoopOptions& o) const {
    prctl(PR_SET_TIMERSLACK, 1UL, 0, 0, 0);
    if (o.priority == LoopPriority::normal) return ObtainedPolicy::normal;
    sched_param fifo{};
    fifo.sched_priority = o.realtime_priority;
    if (pthread_setschedparam(pthread_self(), SCHED_FIFO, &fifo) == 0) return ObtainedPolicy::realtime_fifo;
    if (setpriority(PRIO_PROCESS, tid_, -20) == 0) return ObtainedPolicy::nice_raised;
    return ObtainedPolicy::normal;
  }

 private:
  id_t tid_;
  int slack_;
  int policy_ = SCHED_OTHER;
  sched_param param_{};
  int nice_ = 0;
};

}  // namespace

std::string toString(ObtainedPolicy policy) {
  switch (policy) {
    case ObtainedPolicy::realtime_fifo: return "SCHED_FIFO";
    case ObtainedPolicy::nice_raised: return "nice -20";
    case ObtainedPolicy::normal: break;
  }
  return "normal";
}

void PeriodicLoopOptions::validate() const {
  if (!(period_ms >= 0.05 && period_ms <= 1000.0)) throw InputError("PeriodicLoopOptions.period_ms: must be in 0.05..1000");
  if (realtime_priority < 1 || realtime_priority > 99)
    throw InputError("PeriodicLoopOptions.realtime_priority: must be in 1..99");
}

PeriodicLoop::PeriodicLoop(const PeriodicLoopOptions& options) : options_(options) { options_.validate(); }

PeriodicLoopResult PeriodicLoop::run(long ticks, const std::function<void(long k)>& tick) {
  stop_.store(false, std::memory_order_relaxed);
  const ThreadScheduling scheduling;
  PeriodicLoopResult r;
  r.policy = scheduling.raise(options_);
  if (options_.lock_memory) mlockall(MCL_CURRENT | MCL_FUTURE);
  const auto period = static_cast<long long>(options_.period_ms * 1e6);
  const long limit = ticks < 0 ? std::numeric_limits<long>::max() : ticks;
  if (options_.record_timings && ticks > 0) {  // no reallocation (a copy of every sample so far) inside a tick
    r.wake_latency_us.reserve(static_cast<size_t>(ticks));
    r.work_us.reserve(static_cast<size_t>(ticks));
  }
  const long long start = nowNs() + 2 * period;
  for (long k = 0; k < limit && !stop_.load(std::memory_order_relaxed);) {
    const long long deadline = start + k * period;
    sleepUntil(deadline);
    const long long wake = nowNs();
    const long late_periods = static_cast<long>((wake - deadline) / period);
    if (late_periods > 0) {  // woke after D_{k+1}: those deadlines passed unserved
      const long skipped = std::min(late_periods, limit - k);
      r.missed += skipped;
      r.deadlines += skipped;
      k += skipped;
      if (k >= limit) break;
    }
    const long long due = start + k * period;
    tick(k);
    const long long end = nowNs();
    const double latency_us = static_cast<double>(wake - deadline) * 1e-3, work_us = static_cast<double>(end - wake) * 1e-3;
    r.max_wake_latency_us = std::max(r.max_wake_latency_us, latency_us);
    r.max_work_us = std::max(r.max_work_us, work_us);
    if (options_.record_timings) {
      r.wake_latency_us.push_back(latency_us);
      r.work_us.push_back(work_us);
    }
    ++r.deadlines;
    if (end > due + period) ++r.missed;
    ++k;
  }
  return r;
}

}  // namespace onetip::haptics
