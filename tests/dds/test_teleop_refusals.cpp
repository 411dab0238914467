// tests/dds/test_teleop_refusals.cpp — non-finite or malformed sensed vectors
// never move the platform (docs/dds/README.md, `onetip teleop`): `onetip
// teleop` drives the emulated Maestro while this test publishes NaN, Inf and
// +-1e308 streams (from the start, right after a valid stream, and after a cut)
// and wrong-length and NaN samples amid a valid 100 Hz stream. The platform
// must never leave rest for a bad stream, must be at rest within the stale
// time (+ two driver periods) of the last valid sample when a bad stream takes
// over, and must retract after a single bad sample even while valid samples
// keep coming; teleop must count what it refused.
#include <limits>

#include "child_process.hpp"
#include "teleop_fixture.hpp"

namespace {

using namespace onetip;
using namespace onetip::teleop_test;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// The refused count of teleop's closing line ("received N sensed vectors (R refused)").
long refusedOf(const std::string& log) { return countIn(log, R"(sensed vectors \((\d+) refused\))"); }

struct Window {
  Clock::time_point begin, end;
};

// Around the instant t: the last target period at or before it, the first
// one at rest after it (nullptr when none) and how long after t that came.
struct AroundT {
  const Period* before = nullptr;
  const Period* rest_after = nullptr;
  double rest_ms = 0;
};
AroundT around(const std::vector<Period>& periods, Clock::time_point t, bool (*at_rest)(const Period&)) {
  AroundT at;
  for (const auto& p : periods) {
    if (p.t <= t) at.before = &p;
    if (!at.rest_after && p.t > t && at_rest(p)) at.rest_after = &p;
  }
  if (at.rest_after) at.rest_ms = std::chrono::duration<double, std::milli>(at.rest_after->t - t).count();
  return at;
}

TEST_F(TeleopOverDds, NonFiniteAndHugeStreamsNeverMoveThePlatformAndRetractIt) {
  const std::vector<double> a = rowOf(dataset_, rowWithAngles(dataset_, 90, 130));
  const auto want_a = renderer_.render(a.data(), 4).command;
  const std::vector<double> all_nan(a.size(), kNaN), huge(a.size(), 1e308), minus_huge(a.size(), -1e308);
  const std::vector<double> one_inf = [&] {
    std::vector<double> v = a;
    v[1] = kInf;
    return v;
  }();

  devices::testing::MaestroEmulator maestro;
  test_support::ChildProcess teleop(teleopCommand(maestro.path(), 100, 7.5), dir_.file("teleop.log"));
  dds::Participant participant(net_);
  dds::SensedVectorPublisher publisher(participant, "biotac_like");
  ASSERT_TRUE(waitForReader(publisher)) << teleop.log();

  // Bad streams from the start, then after valid streams with no gap, then after a cut.
  publishFor(publisher, minus_huge, 0.5);
  const Clock::time_point nan_only_end = publishFor(publisher, all_nan, 0.5);
  std::vector<Clock::time_point> last_valid;
  std::vector<Window> bad_after_valid;
  for (const std::vector<double>* bad : {&one_inf, &huge}) {
    last_valid.push_back(publishFor(publisher, a, 1.0));
    const Clock::time_point from = Clock::now();
    bad_after_valid.push_back({from, publishFor(publisher, *bad, 0.5)});
  }
  last_valid.push_back(publishFor(publisher, a, 1.0));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // the real stream stops
  const Clock::time_point nan_after_cut = Clock::now();
  publishFor(publisher, all_nan, 0.5);
  const Clock::time_point nan_end = Clock::now();
  ASSERT_EQ(teleop.wait(30), 0) << teleop.log();
  std::printf("%s", teleop.log().c_str());
  EXPECT_TRUE(maestro.violations().empty());
  EXPECT_GE(refusedOf(teleop.log()), 150) << "about 250 bad samples were sent";

  const std::vector<Period> periods = periodsOf(maestro);
  ASSERT_GT(periods.size(), 100u);
  const double limit_ms = 100.0 + 2 * 1000.0 / options_.rate_hz;
  for (const auto& p : periods) {
    if (p.t <= nan_only_end) {
      EXPECT_TRUE(atRest(p)) << "a -1e308 or NaN stream from the start moved the platform to " << p.deg[0] << " "
                             << p.deg[1] << " " << p.deg[2];
    }
    if (p.t >= nan_after_cut && p.t <= nan_end) {
      EXPECT_TRUE(atRest(p)) << "a NaN stream after the stream stopped moved the platform";
    }
  }
  for (size_t i = 0; i < bad_after_valid.size(); ++i) {
    const AroundT at = around(periods, last_valid[i], atRest);
    ASSERT_NE(at.before, nullptr);
    EXPECT_TRUE(near(*at.before, want_a)) << "bad stream " << i << ": the valid stream before it did not settle";
    ASSERT_NE(at.rest_after, nullptr) << "bad stream " << i << " never retracted the platform";
    std::printf("bad stream %zu: at rest %.1f ms after the last valid sample\n", i, at.rest_ms);
    EXPECT_LE(at.rest_ms, limit_ms) << "bad stream " << i;
    for (const auto& p : periods)
      if (p.t > at.rest_after->t && p.t <= bad_after_valid[i].end) {
        EXPECT_TRUE(atRest(p)) << "bad stream " << i << " moved the platform off rest";
      }
  }
}

TEST_F(TeleopOverDds, OneBadSampleRetractsWhileValidSamplesKeepComing) {
  const std::vector<double> a = rowOf(dataset_, rowWithAngles(dataset_, 90, 130));
  const auto want_a = renderer_.render(a.data(), 4).command;
  const std::vector<double> short_vector(a.begin(), a.end() - 1);
  std::vector<double> one_nan = a;
  one_nan[0] = kNaN;

  devices::testing::MaestroEmulator maestro;
  test_support::ChildProcess teleop(teleopCommand(maestro.path(), 100, 5), dir_.file("teleop.log"));
  dds::Participant participant(net_);
  dds::SensedVectorPublisher publisher(participant, "biotac_like");
  ASSERT_TRUE(waitForReader(publisher)) << teleop.log();
  publishFor(publisher, a, 1.0);
  // Then one bad sample in every 30 of a 100 Hz stream: wrong length and NaN in turn.
  std::vector<Clock::time_point> bad_at;
  auto next = Clock::now();
  for (int k = 1; k <= 180; ++k) {
    const bool bad = k % 30 == 0;
    const std::vector<double>& v = !bad ? a : (bad_at.size() % 2 == 0 ? short_vector : one_nan);
    publisher.publish(std::chrono::duration<double>(Clock::now().time_since_epoch()).count(), v);
    if (bad) bad_at.push_back(Clock::now());
    next += std::chrono::milliseconds(10);
    std::this_thread::sleep_until(next);
  }
  ASSERT_EQ(teleop.wait(30), 0) << teleop.log();
  std::printf("%s", teleop.log().c_str());
  EXPECT_TRUE(maestro.violations().empty());
  EXPECT_EQ(refusedOf(teleop.log()), static_cast<long>(bad_at.size()));

  const std::vector<Period> periods = periodsOf(maestro);
  const double max_step = options_.max_speed_deg_s / options_.rate_hz;
  for (size_t i = 0; i < bad_at.size(); ++i) {
    const AroundT at = around(periods, bad_at[i], atRest);
    ASSERT_NE(at.before, nullptr);
    if (i == 0) {  // later ones may come while the platform is still on its way back from rest
      EXPECT_TRUE(near(*at.before, want_a)) << "not settled on A before the first bad sample";
    }
    ASSERT_NE(at.rest_after, nullptr) << "bad sample " << i << " did not retract the platform";
    // At once (about 1 ms here when the machine is not loaded); the bound is
    // the stale time + two driver periods, what a stall is allowed, so that a
    // loaded machine's scheduling delays do not fail it.
    std::printf("bad sample %zu: at rest %.1f ms after it\n", i, at.rest_ms);
    EXPECT_LE(at.rest_ms, 100.0 + 2 * 1000.0 / options_.rate_hz) << "bad sample " << i;
    // Resuming from rest with the valid samples: at the speed limit, no jump.
    const Period* retracted = at.rest_after;
    const Period* prev = retracted;
    for (const auto& p : periods) {
      if (p.t <= retracted->t || p.t > retracted->t + std::chrono::milliseconds(200)) continue;
      for (size_t c = 0; c < 3; ++c) EXPECT_LE(std::abs(p.deg[c] - prev->deg[c]), max_step + kTol);
      prev = &p;
    }
  }
}

}  // namespace
