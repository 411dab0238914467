// The 3-servo platform driver end to end over a pty against the Maestro
// emulator: configuration bytes, calibrated targets, speed limit, watchdog,
// reconnection and configuration errors at open.
#include <gtest/gtest.h>

#include <cmath>
#include <thread>

#include "core/error.hpp"
#include "devices/servo_platform.hpp"
#include "maestro_emulator.hpp"

namespace onetip::devices {
namespace {

using testing::Clock;
using testing::MaestroEmulator;
using testing::MaestroEvent;

// The default calibration, written out independently: 600 us + 10 us/deg.
int expectedQus(double deg) { return static_cast<int>(std::lround(4.0 * (600.0 + 10.0 * deg))); }
double degreesOf(int qus) { return (qus / 4.0 - 600.0) / 10.0; }

ServoPlatformOptions optionsFor(const MaestroEmulator& emu) {
  ServoPlatformOptions o;
  o.serial.port = emu.path();
  return o;
}

// Last Set Target value per channel.
std::map<int, int> lastTargets(const std::vector<MaestroEvent>& events) {
  std::map<int, int> last;
  for (const auto& e : events)
    if (e.command == 0x84) last[e.channel] = e.value;
  return last;
}

bool targetsAre(const std::vector<MaestroEvent>& events, const std::array<int, 3>& channels,
                const std::array<double, 3>& deg) {
  const auto last = lastTargets(events);
  for (int i = 0; i < 3; ++i) {
    const auto it = last.find(channels[i]);
    if (it == last.end() || it->second != expectedQus(deg[i])) return false;
  }
  return true;
}

TEST(ServoPlatform, SendsSpeedLimitThenCalibratedTargetsPerTheMaestroProtocol) {
  MaestroEmulator emu;
  ServoPlatformOptions o = optionsFor(emu);
  o.channels = {3, 4, 5};
  ServoPlatform platform(o);
  platform.open();
  const std::array<double, 3> goal{90.0, 100.0, 110.0};
  for (int i = 0; i < 20; ++i) {
    platform.command(goal);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_TRUE(testing::waitFor(emu, [&](const auto& ev) { return targetsAre(ev, o.channels, goal); }, 2.0));
  EXPECT_TRUE(emu.violations().empty()) << emu.violations().front();

  // Speed: 60 deg / 0.07 s at 10 us/deg = 8571 us/s = 342.8 (0.25 us / 10 ms), rounded down.
  const auto speeds = emu.events(0x87);
  ASSERT_GE(speeds.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(speeds[i].channel, o.channels[i]);
    EXPECT_EQ(speeds[i].value, 342);
  }
  const auto accels = emu.events(0x89);
  ASSERT_GE(accels.size(), 3u);
  EXPECT_EQ(accels[0].value, 0);
  // Speed and acceleration for all three channels come before the first target.
  const auto all = emu.events();
  for (size_t i = 0; i < 6; ++i) EXPECT_TRUE(all[i].command == 0x87 || all[i].command == 0x89) << i;
  // Get Position requests are answered and read back.
  EXPECT_FALSE(emu.events(0x90).empty());
  ASSERT_TRUE(testing::waitFor(emu, 
      [&](const auto&) {
        const auto m = platform.status().measured;
        return m.size() == 3 && std::abs(m[0] - 90.0) < 0.1 && std::abs(m[2] - 110.0) < 0.1;
      },
      2.0));
}

TEST(ServoPlatform, JumpsAreSpreadAtTheServoSpeedLimitAndRangeIsClamped) {
  MaestroEmulator emu;
  ServoPlatform platform(optionsFor(emu));
  platform.open();
  const std::array<double, 3> goal{500.0, -40.0, 195.0};  // outside the range on both sides
  const auto t0 = Clock::now();
  while (Clock::now() - t0 < std::chrono::milliseconds(400)) {
    platform.command(goal);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  const auto targets = emu.events(0x84);
  std::map<int, double> previous{{0, 30.0}, {1, 30.0}, {2, 30.0}};
  double largest_step = 0.0;
  for (const auto& e : targets) {
    const double deg = degreesOf(e.value);
    EXPECT_GE(deg, 30.0 - 0.03);
    EXPECT_LE(deg, 195.0 + 0.03);
    largest_step = std::max(largest_step, std::abs(deg - previous[e.channel]));
    previous[e.channel] = deg;
  }
  EXPECT_LE(largest_step, 60.0 / 0.07 / 50.0 + 0.05);  // 17.14 deg per 20 ms
  EXPECT_GT(largest_step, 17.0);                         // and it does move at the limit
  EXPECT_TRUE(targetsAre(targets, {0, 1, 2}, {195.0, 30.0, 195.0}));
}

TEST(ServoPlatform, WatchdogRetractsWhenTheInputStalls) {
  MaestroEmulator emu;
  ServoPlatform platform(optionsFor(emu));
  platform.open();
  const std::array<double, 3> goal{60.0, 60.0, 60.0};
  Clock::time_point last_command;
  for (int i = 0; i < 15; ++i) {
    platform.command(goal);
    last_command = Clock::now();
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_TRUE(testing::waitFor(emu, [&](const auto& ev) { return targetsAre(ev, {0, 1, 2}, goal); }, 1.0));
  // No more commands: the rest targets must follow 100 ms after the last one.
  ASSERT_TRUE(testing::waitFor(emu, [&](const auto& ev) { return targetsAre(ev, {0, 1, 2}, {30.0, 30.0, 30.0}); }, 2.0));
  Clock::time_point retracted{};
  for (const auto& e : emu.events(0x84))
    if (e.t > last_command && e.value == expectedQus(30.0) && retracted == Clock::time_point{}) retracted = e.t;
  const double latency_ms = std::chrono::duration<double, std::milli>(retracted - last_command).count();
  RecordProperty("watchdog_latency_ms", std::to_string(latency_ms));
  std::printf("watchdog retraction %.1f ms after the last command\n", latency_ms);
  EXPECT_GE(latency_ms, 99.0);
  EXPECT_LE(latency_ms, 100.0 + 150.0);  // generous margin for a loaded machine
  EXPECT_TRUE(platform.status().retracted);
  EXPECT_EQ(platform.status().retractions, 1u);
}

TEST(ServoPlatform, InputErrorAndNonFiniteGoalsRetractAtOnce) {
  MaestroEmulator emu;
  ServoPlatform platform(optionsFor(emu));
  platform.open();
  const std::array<double, 3> goal{48.0, 48.0, 48.0};
  for (int i = 0; i < 10; ++i) {
    platform.command(goal);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_TRUE(testing::waitFor(emu, [&](const auto& ev) { return targetsAre(ev, {0, 1, 2}, goal); }, 1.0));
  const double nan = std::nan("");
  platform.command(std::array<double, 3>{nan, 40.0, 40.0});
  const auto t0 = Clock::now();
  ASSERT_TRUE(testing::waitFor(emu, [&](const auto& ev) { return targetsAre(ev, {0, 1, 2}, {30.0, 30.0, 30.0}); }, 1.0));
  EXPECT_LT(Clock::now() - t0, std::chrono::milliseconds(100));
  EXPECT_EQ(platform.status().goals_refused, 1u);

  for (int i = 0; i < 10; ++i) {
    platform.command(goal);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_TRUE(testing::waitFor(emu, [&](const auto& ev) { return targetsAre(ev, {0, 1, 2}, goal); }, 1.0));
  platform.reportInputError("tracking lost");
  ASSERT_TRUE(testing::waitFor(emu, [&](const auto& ev) { return targetsAre(ev, {0, 1, 2}, {30.0, 30.0, 30.0}); }, 1.0));
}

TEST(ServoPlatform, ReconnectsAfterThePtyClosesAndReopens) {
  MaestroEmulator emu;
  ServoPlatform platform(optionsFor(emu));
  platform.open();
  std::atomic<bool> feeding{true};
  std::thread feeder([&] {
    while (feeding) {
      platform.command(std::array<double, 3>{70.0, 80.0, 90.0});
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  });
  ASSERT_TRUE(testing::waitFor(emu, [&](const auto& ev) { return targetsAre(ev, {0, 1, 2}, {70.0, 80.0, 90.0}); }, 2.0));
  emu.hangUp();
  const auto down_deadline = Clock::now() + std::chrono::seconds(2);
  while (platform.status().connected && Clock::now() < down_deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_FALSE(platform.status().connected);
  EXPECT_FALSE(platform.status().last_error.empty());
  emu.clear();
  emu.recreate();
  const bool back = testing::waitFor(emu, [&](const auto& ev) { return targetsAre(ev, {0, 1, 2}, {70.0, 80.0, 90.0}); }, 3.0);
  feeding = false;
  feeder.join();
  ASSERT_TRUE(back);
  EXPECT_TRUE(platform.status().connected);
  EXPECT_EQ(platform.status().reconnects, 1u);
  // After reconnecting the speed limit is configured again, then targets restart from rest.
  const auto ev = emu.events();
  ASSERT_FALSE(ev.empty());
  EXPECT_EQ(ev.front().command, 0x87);
  const auto first_target = emu.events(0x84).front();
  EXPECT_EQ(first_target.value, expectedQus(30.0));
  EXPECT_TRUE(emu.violations().empty());
}

TEST(ServoPlatform, BadConfigurationFailsAtOpen) {
  ServoPlatformOptions o;
  o.serial.port = "/dev/onetip-no-such-tty";
  try {
    ServoPlatform(o).open();
    FAIL() << "opened a missing port";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/onetip-no-such-tty"), std::string::npos);
  }
  MaestroEmulator emu;
  o.serial.port = emu.path();
  o.serial.baud = 12345;
  EXPECT_THROW(ServoPlatform(o).open(), InputError);
  o.serial.baud = 460800;  // a termios rate, but beyond the Maestro's 200 kbaud
  EXPECT_THROW(ServoPlatform(o).open(), InputError);
  o.serial.baud = 115200;
  o.channels = {0, 0, 1};
  EXPECT_THROW(ServoPlatform(o).open(), InputError);
  o.channels = {0, 1, 2};
  o.calibration[1].us_per_deg = 20.0;  // 195 deg -> 4500 us: outside the servo's range
  EXPECT_THROW(ServoPlatform(o).open(), InputError);
  o.serial.port = "/dev/null";  // exists, but is not a terminal
  o.calibration[1] = ServoCalibration{};
  EXPECT_THROW(ServoPlatform(o).open(), InputError);
  EXPECT_TRUE(emu.events().empty());  // nothing was sent by the failed opens
}

}  // namespace
}  // namespace onetip::devices
