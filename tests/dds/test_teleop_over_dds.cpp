// tests/dds/test_teleop_over_dds.cpp — `onetip teleop`, the operator side,
// against the emulated Maestro of the servo platform on a pseudo-terminal: a
// remote sensed vector (BioTac-like readings of two dataset configurations)
// is published over DDS for 1 s, stalls for 50 ms, goes on for 0.5 s, is cut
// for 0.5 s, then published again. The Maestro must never get a target outside
// the platform's safe range, must hold through the 50 ms stall, must be
// retracted within the stale time (+ two driver periods) of the last sample,
// stay at rest while the stream is cut, and come back from rest no faster than
// the servos' speed limit, settling on what the kNN renderer gives.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "child_process.hpp"
#include "dds/sensed_vector_link.hpp"
#include "devices/servo_platform.hpp"
#include "haptics/biotac_like_sensor.hpp"
#include "haptics/display_grid.hpp"
#include "haptics/knn_renderer.hpp"
#include "haptics/tactile_dataset.hpp"
#include "maestro_emulator.hpp"
#include "scratch_dir.hpp"

namespace {

using namespace onetip;
using Clock = std::chrono::steady_clock;

std::vector<double> rowOf(const haptics::TactileDataset& d, size_t row) {
  const float* s = d.sensedRow(row);
  return std::vector<double>(s, s + d.channels);
}

// A dataset row whose three angles are all within [lo, hi] deg.
size_t rowWithAngles(const haptics::TactileDataset& d, double lo, double hi) {
  for (size_t r = 0; r < d.size(); ++r) {
    const float* m = d.command(r);
    if (m[0] >= lo && m[0] <= hi && m[1] >= lo && m[1] <= hi && m[2] >= lo && m[2] <= hi) return r;
  }
  return 0;
}

TEST(TeleopOverDds, StreamCutRetractsWithinTheStaleTimeAndResumesAtTheSpeedLimit) {
  test_support::ScratchDir dir("onetip-teleop");
  const haptics::PlatformKinematics kinematics;
  const haptics::BiotacLikeSensor sensor;
  const haptics::TactileDataset dataset = haptics::simulateDataset(kinematics, sensor, 9.0);
  haptics::writeDatasetCsv(dataset, dir.file("dataset.csv"));
  const haptics::KnnRenderer renderer(dataset);
  const std::vector<double> a = rowOf(dataset, rowWithAngles(dataset, 90, 130));
  const std::vector<double> b = rowOf(dataset, rowWithAngles(dataset, 140, 190));
  const auto want_a = renderer.render(a.data(), 4).command, want_b = renderer.render(b.data(), 4).command;

  devices::testing::MaestroEmulator maestro;
  dds::DdsOptions net;
  net.domain = 1 + ::getpid() % 200;
  net.ros_namespace = "onetip_teleop_" + std::to_string(::getpid());
  net.interface = "lo";
  net.peers = {"127.0.0.1"};
  test_support::ChildProcess teleop(std::string(ONETIP_CLI) + " teleop --dataset " + dir.file("dataset.csv") +
                                        " --port " + maestro.path() + " --domain " + std::to_string(net.domain) +
                                        " --namespace " + net.ros_namespace +
                                        " --interface lo --peer 127.0.0.1 --stale-ms 100 --duration 8",
                                    dir.file("teleop.log"));
  dds::Participant participant(net);
  dds::SensedVectorPublisher publisher(participant, "biotac_like");
  const auto give_up = Clock::now() + std::chrono::seconds(20);
  while (publisher.matchedReaders() == 0 && Clock::now() < give_up) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_GT(publisher.matchedReaders(), 0) << teleop.log();

  auto publishFor = [&](const std::vector<double>& v, double seconds) {
    const auto start = Clock::now();
    auto next = start;
    Clock::time_point last{};
    while (Clock::now() - start < std::chrono::duration<double>(seconds)) {
      publisher.publish(std::chrono::duration<double>(Clock::now().time_since_epoch()).count(), v);
      last = Clock::now();
      next += std::chrono::milliseconds(10);  // 100 Hz, as a BioTac
      std::this_thread::sleep_until(next);
    }
    return last;
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

  // The targets the Maestro received, in degrees, per period (one per channel).
  const devices::ServoPlatformOptions options;
  struct Period {
    Clock::time_point t;
    std::array<double, 3> deg;
  };
  std::vector<Period> periods;
  std::array<double, 3> deg{};
  for (const auto& e : maestro.events(0x84)) {
    ASSERT_GE(e.channel, 0);
    ASSERT_LT(e.channel, 3);
    deg[static_cast<size_t>(e.channel)] = options.calibration[static_cast<size_t>(e.channel)].degreesFromQuarterMicroseconds(e.value);
    if (e.channel == 2) periods.push_back({e.t, deg});
  }
  ASSERT_GT(periods.size(), 100u);
  const double rest = 30.0, tol = 0.05;  // a quarter microsecond is ~0.02 deg
  for (const auto& p : periods)
    for (double d : p.deg) {
      EXPECT_GE(d, 30.0 - tol);
      EXPECT_LE(d, 195.0 + tol);
    }

  auto atRest = [&](const Period& p) { return std::abs(p.deg[0] - rest) < tol && std::abs(p.deg[1] - rest) < tol && std::abs(p.deg[2] - rest) < tol; };
  auto near = [&](const Period& p, const std::array<double, 3>& m) {
    return std::abs(p.deg[0] - m[0]) < 0.1 && std::abs(p.deg[1] - m[1]) < 0.1 && std::abs(p.deg[2] - m[2]) < 0.1;
  };
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
  EXPECT_LE(retract_ms, 100.0 + 2 * 1000.0 / options.rate_hz);
  for (const auto& p : periods)
    if (p.t > retracted->t && p.t < resume) {
      EXPECT_TRUE(atRest(p));
    }
  // Resuming: from rest, every step within the speed limit while B streams,
  // settling on B's rendered command (after B the device retracts again: a
  // jump to rest is the one move allowed to be fast).
  const double max_step = options.max_speed_deg_s / options.rate_hz;
  double largest = 0;
  const Period* prev = retracted;
  for (const auto& p : periods) {
    if (p.t <= retracted->t || p.t > last_b) continue;
    for (size_t c = 0; c < 3; ++c) largest = std::max(largest, std::abs(p.deg[c] - prev->deg[c]));
    prev = &p;
  }
  std::printf("largest step after the cut %.2f deg (limit %.2f deg per %.0f ms period)\n", largest, max_step,
              1000.0 / options.rate_hz);
  EXPECT_LE(largest, max_step + tol);
  EXPECT_TRUE(near(*prev, want_b)) << prev->deg[0] << " " << prev->deg[1] << " " << prev->deg[2] << " vs "
                                   << want_b[0] << " " << want_b[1] << " " << want_b[2];
  EXPECT_TRUE(atRest(periods.back()));  // the stream ended: retracted again
}

}  // namespace
