// tests/dds/teleop_fixture.hpp — what the `onetip teleop` tests share: a
// 9-deg BioTac-like dataset written for the command, the loopback DDS set-up
// (domain and namespace from the process id, so parallel runs do not
// cross-talk), the command line, and the emulated Maestro's targets read back
// in degrees, one entry per driver period, each checked against the platform's
// safe range [30, 195] deg.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cmath>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "dds/participant.hpp"
#include "dds/sensed_vector_link.hpp"
#include "devices/servo_platform.hpp"
#include "haptics/biotac_like_sensor.hpp"
#include "haptics/display_grid.hpp"
#include "haptics/knn_renderer.hpp"
#include "haptics/tactile_dataset.hpp"
#include "maestro_emulator.hpp"
#include "scratch_dir.hpp"
#include "test_paths.hpp"

namespace onetip::teleop_test {

using Clock = std::chrono::steady_clock;

inline std::vector<double> rowOf(const haptics::TactileDataset& d, size_t row) {
  const float* s = d.sensedRow(row);
  return std::vector<double>(s, s + d.channels);
}

// A dataset row whose three angles are all within [lo, hi] deg.
inline size_t rowWithAngles(const haptics::TactileDataset& d, double lo, double hi) {
  for (size_t r = 0; r < d.size(); ++r) {
    const float* m = d.command(r);
    if (m[0] >= lo && m[0] <= hi && m[1] >= lo && m[1] <= hi && m[2] >= lo && m[2] <= hi) return r;
  }
  return 0;
}

// The number a pattern's first group matches in a log (e.g. teleop's closing line), -1 when absent.
inline long countIn(const std::string& log, const std::string& pattern) {
  std::smatch m;
  return std::regex_search(log, m, std::regex(pattern)) ? std::stol(m[1]) : -1;
}

// The emulated Maestro's targets in degrees, one entry per driver period.
struct Period {
  Clock::time_point t;
  std::array<double, 3> deg;
};

// How `onetip teleop` is started beyond the defaults: a command prefix (e.g. "ip netns exec NS env
// CYCLONEDDS_URI=..."), its network options, and further options.
struct Launch {
  std::string prefix;
  std::string network = "--interface lo --peer 127.0.0.1";
  std::string extra;
};

class TeleopOverDds : public ::testing::Test {
 protected:
  void SetUp() override {
    haptics::writeDatasetCsv(dataset_, dir_.file("dataset.csv"));
    net_.domain = 1 + ::getpid() % 200;
    net_.ros_namespace = "onetip_teleop_" + std::to_string(::getpid());
    net_.interface = "lo";
    net_.peers = {"127.0.0.1"};
  }

  std::string teleopCommand(const std::string& port, int stale_ms, double duration_s, const Launch& how = {}) const {
    return how.prefix + " " + onetip::test::cliPath() + " teleop --dataset " + dir_.file("dataset.csv") + " --port " +
           port + " --domain " + std::to_string(net_.domain) + " --namespace " + net_.ros_namespace + " " +
           how.network + " --stale-ms " + std::to_string(stale_ms) + " --duration " + std::to_string(duration_s) + " " +
           how.extra;
  }

  // Publishes v at 100 Hz (a BioTac's rate) for `seconds`; returns the time of the last sample.
  static Clock::time_point publishFor(dds::SensedVectorPublisher& publisher, const std::vector<double>& v,
                                      double seconds) {
    const auto start = Clock::now();
    auto next = start;
    Clock::time_point last{};
    while (Clock::now() - start < std::chrono::duration<double>(seconds)) {
      publisher.publish(std::chrono::duration<double>(Clock::now().time_since_epoch()).count(), v);
      last = Clock::now();
      next += std::chrono::milliseconds(10);
      std::this_thread::sleep_until(next);
    }
    return last;
  }
  static bool waitForReader(const dds::SensedVectorPublisher& publisher) {
    const auto give_up = Clock::now() + std::chrono::seconds(20);
    while (publisher.matchedReaders() == 0 && Clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    return publisher.matchedReaders() > 0;
  }

  static std::vector<Period> periodsOf(const devices::testing::MaestroEmulator& maestro) {
    std::vector<Period> periods;
    std::array<double, 3> deg{};
    for (const auto& e : maestro.events(0x84)) {
      EXPECT_TRUE(e.channel >= 0 && e.channel < 3) << "target for channel " << e.channel;
      if (e.channel < 0 || e.channel >= 3) continue;
      deg[static_cast<size_t>(e.channel)] =
          options_.calibration[static_cast<size_t>(e.channel)].degreesFromQuarterMicroseconds(e.value);
      if (e.channel == 2) periods.push_back({e.t, deg});
    }
    for (const auto& p : periods)  // the platform's safe range, [30, 195] deg
      for (double d : p.deg) {
        EXPECT_GE(d, 30.0 - kTol);
        EXPECT_LE(d, 195.0 + kTol);
      }
    return periods;
  }
  static bool atRest(const Period& p) {
    return std::abs(p.deg[0] - kRest) < kTol && std::abs(p.deg[1] - kRest) < kTol && std::abs(p.deg[2] - kRest) < kTol;
  }
  static bool near(const Period& p, const std::array<double, 3>& m) {
    return std::abs(p.deg[0] - m[0]) < 0.1 && std::abs(p.deg[1] - m[1]) < 0.1 && std::abs(p.deg[2] - m[2]) < 0.1;
  }

  static constexpr double kRest = 30.0, kTol = 0.05;  // a quarter microsecond is ~0.02 deg
  static inline const devices::ServoPlatformOptions options_{};
  test_support::ScratchDir dir_{"onetip-teleop"};
  const haptics::PlatformKinematics kinematics_;
  const haptics::BiotacLikeSensor sensor_;
  const haptics::TactileDataset dataset_ = haptics::simulateDataset(kinematics_, sensor_, 9.0);
  const haptics::KnnRenderer renderer_{dataset_};
  dds::DdsOptions net_;
};

}  // namespace onetip::teleop_test
