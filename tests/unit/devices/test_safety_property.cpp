// Property test over every driver: random, extreme and non-finite goals and a
// stalled input never make a device output leave its SafeLimits (range and
// per-command step), as decoded by the firmware emulators; after a stall the
// watchdog retracts within 100 ms (+ a generous scheduling margin).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <thread>

#include "devices/belt_device.hpp"
#include "devices/servo_platform.hpp"
#include "devices/wire_device.hpp"
#include "frame_emulator.hpp"
#include "maestro_emulator.hpp"

namespace onetip::devices {
namespace {

using testing::Clock;

struct Output {
  Clock::time_point t;
  std::vector<double> values;
};

// Drives `device` with hostile goals, then stalls; returns the retraction latency (ms).
double hammer(CutaneousDevice& device, const std::vector<double>& held_goal,
              const std::function<std::vector<Output>()>& outputs, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> wild(-1e3, 1e3), pick(0.0, 1.0);
  const double specials[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity(), 1e300, -1e300, 0.0};
  std::vector<double> goal(device.goalSize());
  const auto t0 = Clock::now();
  while (Clock::now() - t0 < std::chrono::milliseconds(400)) {
    for (double& g : goal) g = pick(rng) < 0.15 ? specials[rng() % 6] : wild(rng);
    device.command(goal);
    if (pick(rng) < 0.05) device.reportInputError("random failure");
    std::this_thread::sleep_for(std::chrono::microseconds(500 + rng() % 3000));
  }
  // A valid goal away from rest for 100 ms, then the input stalls.
  for (int i = 0; i < 20; ++i) {
    device.command(held_goal);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  const auto stall = Clock::now();
  std::this_thread::sleep_for(std::chrono::milliseconds(300));

  const SafeLimits& limits = device.limits();
  const std::vector<Output> sent = outputs();
  EXPECT_GT(sent.size(), 10u);
  std::vector<double> previous = limits.rest();
  Clock::time_point retracted{};
  for (const Output& o : sent) {
    EXPECT_EQ(o.values.size(), limits.outputs.size());
    bool at_rest = true;
    for (size_t i = 0; i < o.values.size(); ++i) {
      const OutputLimit& l = limits.outputs[i];
      const double tolerance = 1e-3 * (l.max - l.min);  // wire quantisation
      EXPECT_GE(o.values[i], l.min - tolerance) << l.name;
      EXPECT_LE(o.values[i], l.max + tolerance) << l.name;
      at_rest = at_rest && std::abs(o.values[i] - l.rest) <= tolerance;
    }
    if (!at_rest) {
      for (size_t i = 0; i < o.values.size(); ++i) {
        const double tolerance = 1e-3 * (limits.outputs[i].max - limits.outputs[i].min);
        EXPECT_LE(std::abs(o.values[i] - previous[i]), limits.maxStep(i) + tolerance) << limits.outputs[i].name;
      }
    }
    if (o.t > stall && at_rest && retracted == Clock::time_point{}) retracted = o.t;
    if (o.t > stall && !at_rest) retracted = {};
    previous = o.values;
  }
  EXPECT_NE(retracted, Clock::time_point{}) << "no retraction after the stall";
  return std::chrono::duration<double, std::milli>(retracted - stall).count();
}

TEST(SafetyProperty, ServoPlatformOutputsStayInRangeAndRetract) {
  testing::MaestroEmulator emu;
  ServoPlatformOptions o;
  o.serial.port = emu.path();
  ServoPlatform device(o);
  device.open();
  const double latency = hammer(device, {100.0, 100.0, 100.0}, [&] {
    std::vector<Output> out;
    std::map<int, double> deg{{0, 30.0}, {1, 30.0}, {2, 30.0}};
    for (const auto& e : emu.events(0x84)) {
      deg[e.channel] = (e.value / 4.0 - 600.0) / 10.0;
      if (e.channel == 2) out.push_back({e.t, {deg[0], deg[1], deg[2]}});
    }
    return out;
  }, 1);
  std::printf("servo platform: retracted %.1f ms after the stall\n", latency);
  EXPECT_LE(latency, 100.0 + 150.0);
  EXPECT_TRUE(emu.violations().empty());
}

TEST(SafetyProperty, BeltDeviceOutputsStayInRangeAndRetract) {
  testing::BeltEmulator emu;
  BeltDeviceOptions o;
  o.serial.port = emu.path();
  o.serial.baud = 921600;
  o.force_points = {{0.25, 120.0}, {0.5, 150.0}, {0.75, 175.0}, {1.0, 200.0}};
  BeltDevice device(o);
  device.open();
  const double latency = hammer(device, {0.5, 0.1}, [&] {
    std::vector<Output> out;
    for (const auto& e : emu.events(0x01)) out.push_back({e.t, e.values});
    return out;
  }, 2);
  std::printf("belt device: retracted %.1f ms after the stall\n", latency);
  EXPECT_LE(latency, 100.0 + 150.0);
  EXPECT_TRUE(emu.violations().empty());
}

TEST(SafetyProperty, WireDeviceOutputsStayInRangeAndRetract) {
  testing::WireEmulator emu;
  WireDeviceOptions o;
  o.serial.port = emu.path();
  WireDevice device(o);
  device.open();
  const double latency = hammer(device, {0.0, 0.0, 0.5}, [&] {
    std::vector<Output> out;
    for (const auto& e : emu.events(0x11)) out.push_back({e.t, e.values});
    return out;
  }, 3);
  std::printf("wire device: retracted %.1f ms after the stall\n", latency);
  EXPECT_LE(latency, 100.0 + 150.0);
  EXPECT_TRUE(emu.violations().empty());
}

TEST(SafetyProperty, WireDeviceRetractsWhenItsSensorsStall) {
  testing::WireEmulator emu;
  WireDeviceOptions o;
  o.serial.port = emu.path();
  WireDevice device(o);
  device.open();
  std::atomic<bool> feeding{true};
  std::thread feeder([&] {
    while (feeding) {
      device.command(std::array<double, 3>{0.0, 0.0, 0.8});
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  });
  auto pulling = [](const std::vector<testing::FrameEvent>& ev) { return !ev.empty() && ev.back().values[0] > 0.05; };
  const bool pulled = testing::waitFor(emu, pulling, 2.0);
  emu.setStreaming(false);
  const auto stalled = Clock::now();
  const bool rested = testing::waitFor(emu, [](const auto& ev) { return !ev.empty() && ev.back().values[0] == 0.0; }, 2.0);
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - stalled).count();
  feeding = false;
  feeder.join();
  EXPECT_TRUE(pulled);
  EXPECT_TRUE(rested);
  std::printf("wire device: PWM 0 %.1f ms after its sensor frames stopped (timeout 50 ms)\n", ms);
  EXPECT_LT(ms, 50.0 + 150.0);
}

}  // namespace
}  // namespace onetip::devices
