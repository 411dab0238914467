// tests/dds/test_teleop_over_dds.cpp — `onetip teleop`, the operator side,
// against the emulated Maestro of the servo platform on a pseudo-terminal: a
// remote sensed vector (BioTac-like readings of two dataset configurations)
// is published over DDS for 1 s, stalls for 50 ms, goes on for 0.5 s, is cut
// for 0.5 s, then published again. The Maestro must never get a target outside
// the platform's safe range, must hold through the 50 ms stall, must be
// retracted within the stale time (+ two driver periods) of the last sample,
// stay at rest while the stream is cut, and come back from rest no faster than
// the servos' speed limit, settling on what the kNN renderer gives. And a
// publisher killed mid-run (SIGKILL: no goodbye on the wire) with the stale
// time set long: DDS liveliness (the writer's 0.5 s lease) must retract the
// platform within the lease, well before the stale timer would.
#include "child_process.hpp"
#include "teleop_fixture.hpp"

namespace {

using namespace onetip;
using namespace onetip::teleop_test;

TEST_F(TeleopOverDds, StreamCutRetractsWithinTheStaleTimeAndResumesAtTheSpeedLimit) {
  const std::vector<double> a = rowOf(dataset_, rowWithAngles(dataset_, 90, 130));
  const std::vector<double> b = rowOf(dataset_, rowWithAngles(dataset_, 140, 190));
  const auto want_a = renderer_.render(a.data(), 4).command, want_b = renderer_.render(b.data(), 4).command;

  devices::testing::MaestroEmulator maestro;
  test_support::ChildProcess teleop(teleopCommand(maestro.path(), 100, 8), dir_.file("teleop.log"));
  dds::Participant participant(net_);
  dds::SensedVectorPublisher publisher(participant, "biotac_like");
  ASSERT_TRUE(waitForReader(publisher)) << teleop.log();
  auto publishFor = [&](const std::vector<double>& v, double seconds) {
    return TeleopOverDds::publishFor(publisher, v, seconds);
  };
  publishFor(a, 1.0);
  const Clock::time_point short_gap = Clock::now();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // a 50 ms stall: shorter than the stale time
  const Clock::time_point last_a = publishFor(a, 0.5);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // the cut
  const Clock::time_point resume = Clock::now();
  const Clock::time_point last_b = publishFor(b, 1.5);
  ASSERT_EQ(teleop.wait(30), 0) << teleop.log();
  std::printf("%s", teleop.log().c_str());
  EXPECT_TRUE(maestro.violations().empty());

  const std::vector<Period> periods = periodsOf(maestro);
  ASSERT_GT(periods.size(), 100u);
  // Before the cut: settled on the rendered command of A.
  const Period* before = nullptr;
  for (const auto& p : periods)
    if (p.t <= last_a) before = &p;
  ASSERT_NE(before, nullptr);
  EXPECT_TRUE(near(*before, want_a)) << before->deg[0] << " " << before->deg[1] << " " << before->deg[2] << " vs "
                                     << want_a[0] << " " << want_a[1] << " " << want_a[2];
  // Through the 50 ms stall the display holds: no retraction, still on A's command.
  for (const auto& p : periods)
    if (p.t > short_gap && p.t <= last_a) {
      EXPECT_FALSE(atRest(p));
      EXPECT_TRUE(near(p, want_a)) << "during the 50 ms stall";
    }
  // After the cut: at rest within the stale time plus two driver periods, and held there until the stream resumes.
  const Period* retracted = nullptr;
  for (const auto& p : periods)
    if (p.t > last_a && atRest(p)) {
      retracted = &p;
      break;
    }
  ASSERT_NE(retracted, nullptr);
  const double retract_ms = std::chrono::duration<double, std::milli>(retracted->t - last_a).count();
  std::printf("retracted %.1f ms after the last sample (stale after 100 ms)\n", retract_ms);
  EXPECT_LE(retract_ms, 100.0 + 2 * 1000.0 / options_.rate_hz);
  for (const auto& p : periods)
    if (p.t > retracted->t && p.t < resume) {
      EXPECT_TRUE(atRest(p));
    }
  // Resuming: from rest, every step within the speed limit while B streams,
  // settling on B's rendered command (after B the device retracts again: a
  // jump to rest is the one move allowed to be fast).
  // The response at the device, end to end: B's first sample published to the
  // first target off rest the Maestro received (DDS, the loop's render and
  // ramp, and the wait for the driver's next 20 ms period). Reported, not bounded.
  for (const auto& p : periods)
    if (p.t > resume && !atRest(p)) {
      std::printf("first target off rest %.1f ms after the stream resumed\n",
                  std::chrono::duration<double, std::milli>(p.t - resume).count());
      break;
    }
  const double max_step = options_.max_speed_deg_s / options_.rate_hz;
  double largest = 0;
  const Period* prev = retracted;
  for (const auto& p : periods) {
    if (p.t <= retracted->t || p.t > last_b) continue;
    for (size_t c = 0; c < 3; ++c) largest = std::max(largest, std::abs(p.deg[c] - prev->deg[c]));
    prev = &p;
  }
  std::printf("largest step after the cut %.2f deg (limit %.2f deg per %.0f ms period)\n", largest, max_step,
              1000.0 / options_.rate_hz);
  EXPECT_LE(largest, max_step + kTol);
  EXPECT_TRUE(near(*prev, want_b)) << prev->deg[0] << " " << prev->deg[1] << " " << prev->deg[2] << " vs "
                                   << want_b[0] << " " << want_b[1] << " " << want_b[2];
  EXPECT_TRUE(atRest(periods.back()));  // the stream ended: retracted again
}

// The publisher is a forked copy of this test publishing A at 100 Hz until it
// is killed with SIGKILL; `onetip teleop` runs with a 2 s stale time, so only
// DDS liveliness (the writer's lease, 0.5 s) can retract it within a second.
TEST_F(TeleopOverDds, KilledPublisherIsNoticedWithinTheLivelinessLease) {
  const std::vector<double> a = rowOf(dataset_, rowWithAngles(dataset_, 90, 130));
  const auto want_a = renderer_.render(a.data(), 4).command;
  const dds::StreamQos qos;  // the writer's lease: qos.lease_s
  test_support::ChildProcess publisher([&] {  // no DDS in this process before the fork
    dds::Participant participant(net_);
    dds::SensedVectorPublisher writer(participant, "biotac_like", qos);
    for (auto next = Clock::now();; next += std::chrono::milliseconds(10)) {
      writer.publish(std::chrono::duration<double>(Clock::now().time_since_epoch()).count(), a);
      std::this_thread::sleep_until(next);
    }
    return 0;
  });
  devices::testing::MaestroEmulator maestro;
  const double stale_s = 2.0;
  test_support::ChildProcess teleop(teleopCommand(maestro.path(), static_cast<int>(stale_s * 1e3), 6),
                                    dir_.file("teleop.log"));

  // Kill the publisher once the platform has held A's command for 0.3 s.
  const auto give_up = Clock::now() + std::chrono::seconds(20);
  auto settled = [&] {
    const auto periods = periodsOf(maestro);
    return !periods.empty() && near(periods.back(), want_a);
  };
  while (!settled() && Clock::now() < give_up) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_TRUE(settled()) << "the platform never settled on A's command\n" << teleop.log();
  const Clock::time_point settled_at = Clock::now();
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  publisher.kill();
  const Clock::time_point killed = Clock::now();
  ASSERT_EQ(teleop.wait(30), 0) << teleop.log();
  std::printf("%s", teleop.log().c_str());
  EXPECT_NE(teleop.log().find("(1: publisher gone)"), std::string::npos) << "teleop did not report the lost writer";

  const std::vector<Period> periods = periodsOf(maestro);
  const Period* retracted = nullptr;
  for (const auto& p : periods) {
    if (p.t <= killed) {
      if (p.t > settled_at) {
        EXPECT_TRUE(near(p, want_a)) << "did not hold A's command while it streamed";
      }
      continue;
    }
    if (!retracted && atRest(p)) retracted = &p;
    if (retracted) {
      EXPECT_TRUE(atRest(p)) << "moved again after retracting, with no publisher";
    }
  }
  ASSERT_NE(retracted, nullptr);
  const double retract_s = std::chrono::duration<double>(retracted->t - killed).count();
  std::printf("retracted %.1f ms after the publisher was killed (lease %.0f ms, stale time %.0f ms)\n",
              retract_s * 1e3, qos.lease_s * 1e3, stale_s * 1e3);
  EXPECT_LE(retract_s, qos.lease_s + 0.1) << "within the lease + 100 ms (the lease check and two driver periods)";
}

}  // namespace
