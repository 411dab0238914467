// The pieces of the 1 kHz loop that keep kNN queries off it: the lock-free
// latest-value slot (never torn, never older than what was fetched before,
// always ending on the last value published), the command ramp, and the worker
// (its results are exactly the renderer's and the table's for the vector it
// answers, and it ends on the newest submission).
#include <gtest/gtest.h>

#include <chrono>
#include <random>
#include <thread>

#include "haptics/command_ramp.hpp"
#include "haptics/latest_value.hpp"
#include "haptics/platform_kinematics.hpp"
#include "haptics/render_worker.hpp"

using namespace onetip::haptics;

namespace {
struct Pair {
  std::uint64_t a = 0, b = 0;  // written equal; a torn read would differ
};
}  // namespace

TEST(LatestValue, ConsumerSeesWholeMonotonicValuesAndTheLastOne) {
  LatestValue<Pair> slot;
  constexpr std::uint64_t kCount = 200000;
  std::thread producer([&] {
    for (std::uint64_t i = 1; i <= kCount; ++i) slot.publish({i, i});
  });
  Pair seen, last;
  std::uint64_t fresh = 0;
  while (last.a < kCount) {
    const bool is_new = slot.fetch(seen);
    ASSERT_EQ(seen.a, seen.b);
    ASSERT_GE(seen.a, last.a);
    if (is_new) {
      ASSERT_GT(seen.a, last.a);
      ++fresh;
    } else {
      ASSERT_EQ(seen.a, last.a);
    }
    last = seen;
  }
  producer.join();
  EXPECT_FALSE(slot.fetch(seen));
  EXPECT_EQ(seen.a, kCount);
  EXPECT_GE(fresh, 1u);
}

TEST(CommandRamp, ReachesTheTargetLinearlyAndRestartsFromWhereItIs) {
  CommandRamp ramp({30, 30, 30}, 10);
  EXPECT_EQ(ramp.step(), (std::array<double, 3>{30, 30, 30}));
  ramp.target({130, 30, 80});
  for (int k = 1; k <= 10; ++k) {
    const auto m = ramp.step();
    EXPECT_NEAR(m[0], 30 + 10.0 * k, 1e-12);
    EXPECT_NEAR(m[2], 30 + 5.0 * k, 1e-12);
  }
  EXPECT_NEAR(ramp.step()[0], 130, 1e-12);  // holds
  ramp.target({30, 30, 30});
  ramp.step();
  ramp.step();  // 2/10 of the way back
  ramp.target({130, 30, 80});
  EXPECT_NEAR(ramp.step()[0], 110 + 2.0, 1e-12);  // from 110, 1/10 of 20
}

TEST(RenderWorker, ResultsAreTheRenderersAndItEndsOnTheNewestSubmission) {
  TactileDataset d;
  d.channels = 3;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> v(0.0, 100.0), angle(30.0, 195.0);
  for (int i = 0; i < 2000; ++i) d.append({angle(rng), angle(rng), angle(rng)}, {v(rng), v(rng), v(rng)});
  const KnnRenderer reference(d), shared(d);
  VibrationTableOptions o;
  o.step_deg = 82.5;  // 30, 112.5 per motor: 8 entries
  o.identification.max_iterations = 0;
  const PlatformKinematics device;
  const VibrationTable table = VibrationTable::identify(simulatedSweepRecorder(device), o);

  std::vector<std::array<double, 3>> queries;
  for (int i = 0; i < 300; ++i) queries.push_back({v(rng), v(rng), v(rng)});
  RenderWorker worker(shared, 4, &table);
  RenderedCommand r;
  EXPECT_FALSE(worker.latest(r));
  EXPECT_EQ(r.sequence, 0u);
  std::uint64_t checked = 0;
  for (size_t i = 0; i < queries.size(); ++i) {
    worker.submit(queries[i].data());
    if (worker.latest(r)) {
      ASSERT_GE(r.sequence, 1u);
      const RenderResult expected = reference.render(queries[r.sequence - 1].data(), 4);
      EXPECT_EQ(r.command, expected.command);
      EXPECT_EQ(r.vibration, &table.lookup(expected.command));
      ++checked;
    }
  }
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (r.sequence != queries.size() && std::chrono::steady_clock::now() < give_up) {
    worker.latest(r);
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
  ASSERT_EQ(r.sequence, queries.size());
  EXPECT_EQ(r.command, reference.render(queries.back().data(), 4).command);
  EXPECT_GE(worker.rendered(), 1u);
  EXPECT_LE(worker.rendered(), queries.size());
  RecordProperty("checked_mid_stream", static_cast<int>(checked));
}
