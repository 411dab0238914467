// The 2-DoF belt device: the per-user angle-force table, the normal/shear to
// motor-angle map, and the driver end to end over a pty against its emulator.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "core/error.hpp"
#include "devices/belt_device.hpp"
#include "frame_emulator.hpp"
#include "scratch_dir.hpp"

namespace onetip::devices {
namespace {

using testing::BeltEmulator;
using testing::Clock;
using testing::FrameEvent;

// A table shaped like the thesis' Fig. 2.3: 25 % of the force at 60 % of the angle.
std::vector<AngleForcePoint> thesisLikePoints() { return {{0.25, 120.0}, {0.5, 150.0}, {0.75, 175.0}, {1.0, 200.0}}; }

// Files written here go to one scratch directory, removed when the test process exits.
std::string writeFile(const std::string& name, const std::string& text) {
  static const onetip::test_support::ScratchDir scratch("onetip-devices");
  const std::string path = scratch.file(name);
  std::ofstream(path) << text;
  return path;
}

TEST(BeltForceTable, InterpolatesPiecewiseLinearlyThroughTheProcedurePoints) {
  const BeltForceTable t = BeltForceTable::fromPoints(thesisLikePoints());
  EXPECT_DOUBLE_EQ(t.angleFor(0.0), 0.0);
  EXPECT_DOUBLE_EQ(t.angleFor(0.25), 120.0);  // the break: 60 % of the angle at 25 % force
  EXPECT_DOUBLE_EQ(t.angleFor(0.125), 60.0);  // first line: 480 deg per unit force
  EXPECT_DOUBLE_EQ(t.angleFor(0.375), 135.0);
  EXPECT_DOUBLE_EQ(t.angleFor(0.9), 190.0);
  EXPECT_DOUBLE_EQ(t.angleFor(2.0), 200.0);   // clamped
  EXPECT_DOUBLE_EQ(t.angleFor(-1.0), 0.0);
  for (double f = 0.0; f <= 1.0; f += 0.05) EXPECT_NEAR(t.forceFor(t.angleFor(f)), f, 1e-12);
}

TEST(BeltForceTable, RoundTripsItsCsvAndRejectsMalformedTables) {
  const std::string path = writeFile("table.csv", "force_percent,angle_deg\n25,120\n50,150\n75,175\n100,200\n");
  const BeltForceTable t = BeltForceTable::load(path);
  EXPECT_DOUBLE_EQ(t.angleFor(0.5), 150.0);
  const std::string copy = path + ".copy.csv";
  t.save(copy);
  EXPECT_DOUBLE_EQ(BeltForceTable::load(copy).angleFor(0.6), t.angleFor(0.6));
  auto expectBad = [](const std::string& text, const std::string& mention) {
    const std::string bad = writeFile("bad.csv", text);
    try {
      BeltForceTable::load(bad);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(mention), std::string::npos) << e.what();
    }
  };
  expectBad("force_percent,angle_deg\n25,120\n50,110\n100,200\n", "angle must increase");
  expectBad("force_percent,angle_deg\n25,120\n50,150\n75,175\n", "100 %");
  expectBad("force_percent,angle_deg\n50,150\n100,200\n", "three");
  expectBad("force_percent,angle_deg\n25,abc\n50,150\n100,200\n", "angle_deg");
  expectBad("force,angle\n25,1\n50,2\n100,3\n", "force_percent");
  std::filesystem::remove(path);
  std::filesystem::remove(copy);
}

TEST(BeltDevice, NormalForceTurnsTheMotorsOppositeAndShearTheSameWay) {
  const BeltForceTable t = BeltForceTable::fromPoints(thesisLikePoints());
  auto m = BeltDevice::motorAngles(t, 2.0, 0.5, 0.0);  // 25 % normal
  EXPECT_DOUBLE_EQ(m[0], 120.0);
  EXPECT_DOUBLE_EQ(m[1], -120.0);
  m = BeltDevice::motorAngles(t, 2.0, 0.0, -0.25);  // 12.5 % shear backwards
  EXPECT_DOUBLE_EQ(m[0], -60.0);
  EXPECT_DOUBLE_EQ(m[1], -60.0);
  m = BeltDevice::motorAngles(t, 2.0, 1.5, 1.0);  // 75 % normal leaves 25 deg for shear
  EXPECT_DOUBLE_EQ(m[0], 200.0);
  EXPECT_DOUBLE_EQ(m[1], -150.0);
}

BeltDeviceOptions optionsFor(const BeltEmulator& emu) {
  BeltDeviceOptions o;
  o.serial.port = emu.path();
  o.serial.baud = 921600;
  o.force_points = thesisLikePoints();
  o.max_force_n = 1.0;
  return o;
}

TEST(BeltDevice, DriverSpeaksTheDocumentedFramesAndReadsEncodersAtOneKilohertz) {
  BeltEmulator emu;
  BeltDevice device(optionsFor(emu));
  device.open();
  const auto t0 = Clock::now();
  while (Clock::now() - t0 < std::chrono::milliseconds(600)) {
    device.command(std::array<double, 2>{0.5, 0.0});  // 50 % normal: +-150 deg
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_TRUE(emu.violations().empty()) << emu.violations().front();
  const auto all = emu.events();
  ASSERT_FALSE(all.empty());
  EXPECT_EQ(all.front().type, 0x02);
  EXPECT_EQ(all.front().values[0], 1000.0);
  const auto angles = emu.events(0x01);
  ASSERT_FALSE(angles.empty());
  EXPECT_NEAR(angles.back().values[0], 150.0, 1e-3);
  EXPECT_NEAR(angles.back().values[1], -150.0, 1e-3);
  // Ramp at 720 deg/s and 1 kHz: at most 0.72 deg per frame.
  double largest = 0.0;
  for (size_t i = 1; i < angles.size(); ++i)
    largest = std::max(largest, std::abs(angles[i].values[0] - angles[i - 1].values[0]));
  EXPECT_LE(largest, 0.72 + 1e-3);
  // Frames per second actually sent by the driver loop.
  const double span_s = std::chrono::duration<double>(angles.back().t - angles.front().t).count();
  const double sent_hz = (angles.size() - 1) / span_s;
  std::printf("belt driver: %.0f SET_ANGLES frames/s (nominal 1000)\n", sent_hz);
  EXPECT_GT(sent_hz, 300.0);  // loose: the machine is shared
  const auto measured = device.status().measured;
  ASSERT_EQ(measured.size(), 2u);
  EXPECT_NEAR(measured[0], 150.0, 0.01);  // 65536 counts/rev: 0.0055 deg per count
  EXPECT_NEAR(measured[1], -150.0, 0.01);
}

TEST(BeltDevice, ReconnectsAfterThePtyClosesAndReopens) {
  BeltEmulator emu;
  BeltDevice device(optionsFor(emu));
  device.open();
  std::atomic<bool> feeding{true};
  std::thread feeder([&] {
    while (feeding) {
      device.command(std::array<double, 2>{0.25, 0.0});
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  });
  auto at120 = [](const std::vector<FrameEvent>& ev) {
    for (auto it = ev.rbegin(); it != ev.rend(); ++it)
      if (it->type == 0x01) return std::abs(it->values[0] - 120.0) < 1e-3;
    return false;
  };
  ASSERT_TRUE(testing::waitFor(emu, at120, 2.0));
  emu.hangUp();
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_FALSE(device.status().connected);
  emu.clear();
  emu.recreate();
  const bool back = testing::waitFor(emu, at120, 3.0);
  feeding = false;
  feeder.join();
  ASSERT_TRUE(back);
  EXPECT_EQ(emu.events().front().type, 0x02);  // the feedback rate is configured again
  EXPECT_EQ(device.status().reconnects, 1u);
}

TEST(BeltDevice, BadConfigurationFailsBeforeAnythingIsSent) {
  BeltEmulator emu;
  BeltDeviceOptions o = optionsFor(emu);
  o.force_table_csv = writeFile("malformed.csv", "force_percent,angle_deg\n25,120\n50,100\n100,200\n");
  EXPECT_THROW(BeltDevice{o}, InputError);
  o.force_table_csv = "/nonexistent/table.csv";
  EXPECT_THROW(BeltDevice{o}, InputError);
  o.force_table_csv.clear();
  o.serial.baud = 250000;
  EXPECT_THROW(BeltDevice(o).open(), InputError);
  o.serial.baud = 921600;
  o.serial.port = "/dev/onetip-missing";
  EXPECT_THROW(BeltDevice(o).open(), InputError);
  o.serial.port = emu.path();
  o.feedback_rate_hz = 5000;
  EXPECT_THROW(BeltDevice(o).open(), InputError);
  EXPECT_TRUE(emu.events().empty());
}

}  // namespace
}  // namespace onetip::devices
