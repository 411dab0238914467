// PeriodicLoop bookkeeping: tick order, deadline accounting when a tick
// overruns or the thread sleeps through deadlines, stop(), option checks, and
// that the thread's scheduling is restored. No timing figures are asserted
// (speed lives in tests/bench/haptics/render_loop_main.cpp); only lower
// bounds that any machine satisfies.
#include <gtest/gtest.h>
#include <pthread.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include "core/error.hpp"
#include "haptics/periodic_loop.hpp"

using namespace onetip;
using namespace onetip::haptics;

TEST(PeriodicLoop, RunsEveryTickInOrderWhenWorkIsShort) {
  PeriodicLoopOptions o;
  o.priority = LoopPriority::normal;
  o.record_timings = true;
  PeriodicLoop loop(o);
  std::vector<long> seen;
  const PeriodicLoopResult r = loop.run(20, [&](long k) { seen.push_back(k); });
  EXPECT_EQ(r.deadlines, 20);
  // On a loaded machine a tick may be skipped, but ticks never repeat or go backwards,
  // and every deadline is either run or counted as missed.
  ASSERT_FALSE(seen.empty());
  for (size_t i = 1; i < seen.size(); ++i) EXPECT_GT(seen[i], seen[i - 1]);
  EXPECT_GE(r.missed, 20 - static_cast<long>(seen.size()));
  EXPECT_EQ(r.wake_latency_us.size(), seen.size());
  EXPECT_EQ(r.work_us.size(), seen.size());
}

TEST(PeriodicLoop, AnOverrunningTickCountsItselfAndTheDeadlinesItSleptThrough) {
  PeriodicLoopOptions o;
  o.priority = LoopPriority::normal;
  PeriodicLoop loop(o);
  std::vector<long> seen;
  long overran = -1;  // the first tick run at or after k = 5 (a loaded machine may skip some)
  const PeriodicLoopResult r = loop.run(30, [&](long k) {
    seen.push_back(k);
    if (overran < 0 && k >= 5) {
      overran = k;
      std::this_thread::sleep_for(std::chrono::microseconds(4500));  // ends after D_{k+4}
    }
  });
  EXPECT_EQ(r.deadlines, 30);
  ASSERT_GE(overran, 5);
  ASSERT_LT(overran, 25);
  // The overrunning tick missed (it ended after D_{k+1}), and the loop woke for
  // D_{k+1} after D_{k+4}: D_{k+1} .. D_{k+3} are counted missed and their
  // ticks are not run. At least 4 misses (a loaded machine adds more, never fewer).
  EXPECT_GE(r.missed, 4);
  for (long skipped = overran + 1; skipped <= overran + 3; ++skipped)
    EXPECT_EQ(std::count(seen.begin(), seen.end(), skipped), 0);
  EXPECT_GE(r.max_work_us, 4500.0);
}

TEST(PeriodicLoop, StopEndsTheLoopAfterTheCurrentTick) {
  PeriodicLoopOptions o;
  o.priority = LoopPriority::normal;
  PeriodicLoop loop(o);
  long last = -1;
  const PeriodicLoopResult r = loop.run(-1, [&](long k) {
    last = k;
    if (k >= 10) loop.stop();
  });
  EXPECT_GE(last, 10);
  EXPECT_LE(last, 10 + r.missed);  // only deadlines skipped before tick 10 can push it past 10
}

TEST(PeriodicLoop, RestoresTheThreadsSchedulingAfterRaisingIt) {
  int policy_before = 0;
  sched_param param_before{};
  pthread_getschedparam(pthread_self(), &policy_before, &param_before);
  const auto tid = static_cast<id_t>(syscall(SYS_gettid));
  const int nice_before = getpriority(PRIO_PROCESS, tid);
  PeriodicLoop loop;  // best_available: SCHED_FIFO or nice -20 where permitted
  const PeriodicLoopResult r = loop.run(5, [](long) {});
  int policy_after = 0;
  sched_param param_after{};
  pthread_getschedparam(pthread_self(), &policy_after, &param_after);
  EXPECT_EQ(policy_after, policy_before) << "obtained " << toString(r.policy);
  EXPECT_EQ(param_after.sched_priority, param_before.sched_priority);
  EXPECT_EQ(getpriority(PRIO_PROCESS, tid), nice_before);
}

TEST(PeriodicLoop, RejectsBadOptions) {
  PeriodicLoopOptions o;
  o.period_ms = 0.0;
  EXPECT_THROW(PeriodicLoop{o}, InputError);
  o = {};
  o.realtime_priority = 100;
  EXPECT_THROW(PeriodicLoop{o}, InputError);
}
