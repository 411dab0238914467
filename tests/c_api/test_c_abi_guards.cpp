// The C ABI's refusals that keep a host from deadlocking (issue 17): waiting on
// a sensor from its own callback, two callbacks stopping each other's sensors,
// time-outs of INFINITY / 1e300 (which returned at once) or NaN, and (issue 39)
// a wait without limit on a sensor never started, released by its destruction.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <cmath>
#include <string>
#include <thread>

#include "onetip_c.h"
#include "test_paths.hpp"

namespace {

const std::string kSource = std::string("sim:") + onetip::test::sourceDir() + "/samples/scenarios/press.yaml";

onetip_sensor* makeSensor() {
  onetip_error err;
  onetip_sensor* s = nullptr;
  EXPECT_EQ(onetip_sensor_create(ONETIP_C_ABI_VERSION, kSource.c_str(), nullptr, nullptr, nullptr, nullptr, &s, &err),
            ONETIP_OK)
      << err.message;
  return s;
}

struct SelfWait {
  onetip_sensor* self = nullptr;
  std::atomic<int> calls{0};
  std::atomic<int> wait_finished_kind{-1}, wait_event_kind{-1};
};

void waitOnSelf(const onetip_frame*, const onetip_marker*, int32_t, void* user) {
  auto* w = static_cast<SelfWait*>(user);
  if (w->calls.fetch_add(1) != 0) return;
  onetip_error err;
  int32_t finished = 0, got = 0;
  onetip_event e;
  onetip_sensor_wait_finished(w->self, -1, &finished, &err);
  w->wait_finished_kind = err.kind;
  onetip_sensor_wait_event(w->self, INFINITY, &e, &got, &err);
  w->wait_event_kind = err.kind;
}

TEST(CAbiGuards, WaitingOnTheSensorFromItsOwnCallbackIsAStateError) {
  SelfWait w;
  w.self = makeSensor();
  ASSERT_NE(w.self, nullptr);
  onetip_error err;
  ASSERT_EQ(onetip_sensor_set_frame_callback(w.self, waitOnSelf, &w, &err), ONETIP_OK) << err.message;
  ASSERT_EQ(onetip_sensor_start(w.self, &err), ONETIP_OK) << err.message;
  int32_t finished = 0;
  ASSERT_EQ(onetip_sensor_wait_finished(w.self, 300, &finished, &err), ONETIP_OK) << err.message;
  EXPECT_EQ(finished, 1);
  EXPECT_GT(w.calls.load(), 0);
  EXPECT_EQ(w.wait_finished_kind.load(), ONETIP_ERROR_STATE);
  EXPECT_EQ(w.wait_event_kind.load(), ONETIP_ERROR_STATE);
  EXPECT_EQ(onetip_sensor_destroy(w.self, &err), ONETIP_OK) << err.message;
}

struct CrossStop {
  onetip_sensor* other = nullptr;
  std::atomic<int>* inside = nullptr;  // callbacks of both sensors that have started
  std::atomic<int>* stopped = nullptr;  // ... and that have called stop
  std::atomic<int> calls{0};
  std::atomic<int> stop_kind{-1};
};

// Waits (at most 20 s) until `count` reaches 2.
void bothAt(const std::atomic<int>& count) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (count.load() < 2 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

void stopTheOther(const onetip_frame*, const onetip_marker*, int32_t, void* user) {
  auto* c = static_cast<CrossStop*>(user);
  if (c->calls.fetch_add(1) != 0) return;
  // both callbacks run at once and stay until both called stop: each stop would wait for the other's callback
  c->inside->fetch_add(1);
  bothAt(*c->inside);
  onetip_error err;
  onetip_sensor_stop(c->other, &err);
  c->stop_kind = err.kind;
  c->stopped->fetch_add(1);
  bothAt(*c->stopped);
}

TEST(CAbiGuards, CallbacksStoppingEachOthersSensorsAreRefusedNotDeadlocked) {
  std::atomic<int> inside{0}, stopped{0};
  CrossStop a, b;
  onetip_sensor* sa = makeSensor();
  onetip_sensor* sb = makeSensor();
  ASSERT_TRUE(sa && sb);
  a.other = sb;
  b.other = sa;
  a.inside = b.inside = &inside;
  a.stopped = b.stopped = &stopped;
  onetip_error err;
  ASSERT_EQ(onetip_sensor_set_frame_callback(sa, stopTheOther, &a, &err), ONETIP_OK);
  ASSERT_EQ(onetip_sensor_set_frame_callback(sb, stopTheOther, &b, &err), ONETIP_OK);
  ASSERT_EQ(onetip_sensor_start(sa, &err), ONETIP_OK) << err.message;
  ASSERT_EQ(onetip_sensor_start(sb, &err), ONETIP_OK) << err.message;
  int32_t finished = 0;
  ASSERT_EQ(onetip_sensor_wait_finished(sa, 300, &finished, &err), ONETIP_OK) << err.message;
  ASSERT_EQ(onetip_sensor_wait_finished(sb, 300, &finished, &err), ONETIP_OK) << err.message;
  EXPECT_EQ(inside.load(), 2);
  EXPECT_EQ(a.stop_kind.load(), ONETIP_ERROR_STATE);
  EXPECT_EQ(b.stop_kind.load(), ONETIP_ERROR_STATE);
  EXPECT_EQ(onetip_sensor_destroy(sa, &err), ONETIP_OK) << err.message;
  EXPECT_EQ(onetip_sensor_destroy(sb, &err), ONETIP_OK) << err.message;
}

TEST(CAbiGuards, InfiniteAndHugeTimeoutsWaitWithoutLimitAndNaNIsRefused) {
  for (const double timeout : {static_cast<double>(INFINITY), 1e300}) {
    onetip_sensor* s = makeSensor();
    ASSERT_NE(s, nullptr);
    onetip_error err;
    onetip_event e;
    int32_t got = 0, finished = 0;
    ASSERT_EQ(onetip_sensor_start(s, &err), ONETIP_OK) << err.message;
    ASSERT_EQ(onetip_sensor_wait_event(s, timeout, &e, &got, &err), ONETIP_OK) << err.message;
    EXPECT_EQ(got, 1) << "returned without an event while running";
    ASSERT_EQ(onetip_sensor_wait_finished(s, timeout, &finished, &err), ONETIP_OK) << err.message;
    EXPECT_EQ(finished, 1) << "returned before the end";
    EXPECT_EQ(onetip_sensor_wait_finished(s, NAN, &finished, &err), ONETIP_ERROR_INPUT);
    EXPECT_EQ(onetip_sensor_wait_event(s, NAN, &e, &got, &err), ONETIP_ERROR_INPUT);
    EXPECT_EQ(onetip_sensor_destroy(s, &err), ONETIP_OK) << err.message;
  }
}

// Waits without limit on `s` in another thread; the future holds the call's status and `finished`.
std::future<std::pair<int32_t, int32_t>> waitFinishedElsewhere(onetip_sensor* s) {
  std::promise<std::pair<int32_t, int32_t>> returned;
  auto result = returned.get_future();
  std::thread([s, p = std::move(returned)]() mutable {
    onetip_error err;
    int32_t finished = -1;
    const int32_t status = onetip_sensor_wait_finished(s, INFINITY, &finished, &err);
    p.set_value({status, finished});
  }).detach();  // detached: a waiter that never returns fails the test instead of hanging it
  return result;
}

TEST(CAbiGuards, AWaitWithoutLimitOnASensorNeverStartedReturnsWhenAnotherThreadDestroysIt) {
  onetip_sensor* s = makeSensor();
  ASSERT_NE(s, nullptr);
  auto waiter = waitFinishedElsewhere(s);
  // Nothing ends a sensor nobody started: the waiter waits (for a start, or as here a destruction).
  ASSERT_EQ(waiter.wait_for(std::chrono::milliseconds(300)), std::future_status::timeout);
  onetip_error err;
  ASSERT_EQ(onetip_sensor_destroy(s, &err), ONETIP_OK) << err.message;
  ASSERT_EQ(waiter.wait_for(std::chrono::seconds(30)), std::future_status::ready) << "the waiter never returned";
  EXPECT_EQ(waiter.get(), std::make_pair(int32_t{ONETIP_OK}, int32_t{0}));  // returned, not finished
}

TEST(CAbiGuards, AStopBeforeStartEndsTheSensorForWaitersAndItNeverStarts) {
  onetip_sensor* s = makeSensor();
  ASSERT_NE(s, nullptr);
  onetip_error err;
  ASSERT_EQ(onetip_sensor_stop(s, &err), ONETIP_OK) << err.message;
  auto waiter = waitFinishedElsewhere(s);
  ASSERT_EQ(waiter.wait_for(std::chrono::seconds(30)), std::future_status::ready) << "the waiter never returned";
  EXPECT_EQ(waiter.get(), std::make_pair(int32_t{ONETIP_OK}, int32_t{0}));
  EXPECT_EQ(onetip_sensor_start(s, &err), ONETIP_ERROR_STATE);
  EXPECT_EQ(onetip_sensor_destroy(s, &err), ONETIP_OK) << err.message;
}

}  // namespace
