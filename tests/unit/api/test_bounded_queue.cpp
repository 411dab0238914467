// BoundedQueue (latest wins / lossless / close) and the timing statistics,
// against brute-force references.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <thread>

#include "pipeline/bounded_queue.hpp"
#include "pipeline/timing_stats.hpp"

namespace onetip::pipeline {
namespace {

TEST(BoundedQueue, LatestWinsDropsTheOldestAndCountsIt) {
  BoundedQueue<int> q(3);
  for (int i = 0; i < 10; ++i) q.push(i);
  EXPECT_EQ(q.size(), 3u);
  EXPECT_EQ(q.dropped(), 7);
  int v = -1;
  for (int expected : {7, 8, 9}) {
    ASSERT_TRUE(q.tryPop(v));
    EXPECT_EQ(v, expected);
  }
  EXPECT_FALSE(q.tryPop(v));
}

TEST(BoundedQueue, LosslessPushWaitsForRoomAndKeepsEverything) {
  BoundedQueue<int> q(2);
  std::thread producer([&] {
    for (int i = 0; i < 200; ++i) q.push(i, /*wait_for_room=*/true);
    q.close();
  });
  std::vector<int> got;
  int v;
  while (q.waitPop(v, std::chrono::seconds(-1))) {
    EXPECT_LE(q.size(), 2u);
    got.push_back(v);
  }
  producer.join();
  ASSERT_EQ(got.size(), 200u);
  for (int i = 0; i < 200; ++i) EXPECT_EQ(got[static_cast<size_t>(i)], i);
  EXPECT_EQ(q.dropped(), 0);
}

TEST(BoundedQueue, CloseWakesAWaitingProducerAndDrains) {
  BoundedQueue<int> q(1);
  q.push(1);
  std::thread producer([&] { EXPECT_EQ(q.push(2, true), BoundedQueue<int>::PushResult::closed); });
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  q.close();
  producer.join();
  int v = 0;
  EXPECT_TRUE(q.waitPop(v, std::chrono::milliseconds(10)));
  EXPECT_EQ(v, 1);
  EXPECT_FALSE(q.waitPop(v, std::chrono::seconds(-1)));  // closed and empty: no wait
  EXPECT_EQ(q.push(3), BoundedQueue<int>::PushResult::closed);
}

TEST(TimingStats, MedianAndP99MatchSortedOrderStatisticsOverTheWindow) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 10);
  TimingStats stats({"a"}, 500);
  std::vector<double> all;
  for (int i = 0; i < 1300; ++i) {
    all.push_back(u(rng));
    stats.add(0, all.back());
  }
  std::vector<double> window(all.end() - 500, all.end());
  std::sort(window.begin(), window.end());
  const StageSummary s = stats.summary().at(0);
  EXPECT_EQ(s.count, 500);
  EXPECT_DOUBLE_EQ(s.median_ms, 0.5 * (window[249] + window[250]));
  EXPECT_DOUBLE_EQ(s.p99_ms, window[494]);  // nearest rank: ceil(0.99 * 500) = 495th smallest
  EXPECT_DOUBLE_EQ(s.max_ms, window.back());
}

}  // namespace
}  // namespace onetip::pipeline
