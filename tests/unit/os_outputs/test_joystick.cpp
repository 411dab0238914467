// The uinput joystick without a kernel: its axis scaling, the device it
// declares, the evdev event stream (written through a pipe standing in for
// /dev/uinput) and the errors for missing or wrong device nodes. Expected
// values are worked out by hand from axis_scaling.hpp: the working range maps
// linearly onto [-32767, 32767]. The kernel side is checked under qemu
// (tests/qemu_uinput).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "core/error.hpp"
#include "os_outputs/uinput_joystick.hpp"
#include "test_support.hpp"

namespace onetip::os_outputs {
namespace {

using input::EventType;
using input::InputEvent;

struct Ev {
  int type, code, value;
  bool operator==(const Ev&) const = default;
};
std::vector<Ev> simplify(const std::vector<input_event>& events) {
  std::vector<Ev> out;
  for (const auto& e : events) out.push_back({e.type, e.code, e.value});
  return out;
}
void PrintTo(const Ev& e, std::ostream* os) { *os << "{" << e.type << "," << e.code << "," << e.value << "}"; }

InputEvent event(EventType type, Input6 in = {}) { return testing::makeEvent(type, 0, in); }

std::string openError(const std::string& node) {
  UinputJoystickOptions o;
  o.node = node;
  UinputJoystick j(o);
  try {
    j.open();
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

TEST(JoystickScaling, WorkingRangeMapsOntoTheSint16Range) {
  const WorkingRange range;
  EXPECT_EQ(joystickAxes(Input6{}, range), (std::array<std::int32_t, 6>{0, 0, -32767, 0, 0, 0}));
  Input6 in;
  in.dx = 1;       // 0.25 * 32767 = 8191.75 -> 8192
  in.dy = -4;      // the low end
  in.dz = 1.5;     // the middle of [0, 3]
  in.pitch = 20;   // 0.5 * 32767 = 16383.5 -> 16384
  in.roll = -10;   // -8191.75 -> -8192
  in.yaw = 15;     // the high end
  EXPECT_EQ(joystickAxes(in, range), (std::array<std::int32_t, 6>{8192, -32767, 0, 16384, -8192, 32767}));
  in = Input6{};
  in.dx = 9;       // clamped
  in.dz = -1;      // lifting: clamped to the low end
  in.yaw = std::nan("");
  EXPECT_EQ(joystickAxes(in, range), (std::array<std::int32_t, 6>{32767, 0, -32767, 0, 0, 0}));
}

TEST(JoystickDevice, DeclaresSixAxesAndATriggerButton) {
  JoystickDeviceOptions o;
  const JoystickDescription d = describeJoystick(o);
  EXPECT_STREQ(d.setup.name, "onetip tactile joystick");
  EXPECT_EQ(d.setup.id.bustype, BUS_VIRTUAL);
  const int codes[] = {ABS_X, ABS_Y, ABS_Z, ABS_RX, ABS_RY, ABS_RZ};
  const int rest[] = {0, 0, -32767, 0, 0, 0};
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(d.axes[static_cast<size_t>(i)].code, codes[i]);
    EXPECT_EQ(d.axes[static_cast<size_t>(i)].absinfo.minimum, -32767);
    EXPECT_EQ(d.axes[static_cast<size_t>(i)].absinfo.maximum, 32767);
    EXPECT_EQ(d.axes[static_cast<size_t>(i)].absinfo.value, rest[i]);
  }
  EXPECT_EQ(d.keys, std::vector<int>{BTN_TRIGGER});
  o.name = std::string(100, 'n');
  try {
    describeJoystick(o);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("name"), std::string::npos) << e.what();
  }
}

TEST(JoystickEncoder, EmitsChangesButtonsAndTheRestAtContactEnd) {
  JoystickEncoder enc{WorkingRange{}};
  EXPECT_TRUE(enc.onEvent(event(EventType::contact_begin)).empty());
  Input6 in;
  in.dx = 1;
  in.pitch = 20;
  EXPECT_EQ(simplify(enc.onEvent(event(EventType::input, in))),
            (std::vector<Ev>{{EV_ABS, ABS_X, 8192}, {EV_ABS, ABS_RX, 16384}, {EV_SYN, SYN_REPORT, 0}}));
  EXPECT_TRUE(enc.onEvent(event(EventType::input, in)).empty());  // nothing changed
  EXPECT_EQ(simplify(enc.onEvent(event(EventType::press))),
            (std::vector<Ev>{{EV_KEY, BTN_TRIGGER, 1}, {EV_SYN, SYN_REPORT, 0}}));
  EXPECT_TRUE(enc.onEvent(event(EventType::press)).empty());  // already down
  in.dz = 3;
  EXPECT_EQ(simplify(enc.onEvent(event(EventType::input, in))),
            (std::vector<Ev>{{EV_ABS, ABS_Z, 32767}, {EV_SYN, SYN_REPORT, 0}}));
  // Contact end with the button still down: release, then every axis to rest.
  EXPECT_EQ(simplify(enc.onEvent(event(EventType::contact_end))),
            (std::vector<Ev>{{EV_KEY, BTN_TRIGGER, 0},
                             {EV_ABS, ABS_X, 0},
                             {EV_ABS, ABS_Z, -32767},
                             {EV_ABS, ABS_RX, 0},
                             {EV_SYN, SYN_REPORT, 0}}));
  EXPECT_TRUE(enc.onEvent(event(EventType::release)).empty());  // not down any more
  EXPECT_TRUE(enc.onEvent(event(EventType::error)).empty());
}

TEST(JoystickEncoder, StreamThroughAPipeIsWhatUinputWouldRead) {
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  JoystickEncoder enc{WorkingRange{}};
  Input6 in;
  in.dy = 2;      // 16383.5 -> 16384
  in.yaw = -7.5;  // -16384
  const auto events = enc.onEvent(event(EventType::input, in));
  writeInputEvents(fds[1], events, "test pipe");
  std::vector<input_event> back(events.size());
  const size_t bytes = back.size() * sizeof(input_event);
  ASSERT_EQ(::read(fds[0], back.data(), bytes), static_cast<ssize_t>(bytes));
  EXPECT_EQ(simplify(back),
            (std::vector<Ev>{{EV_ABS, ABS_Y, 16384}, {EV_ABS, ABS_RZ, -16384}, {EV_SYN, SYN_REPORT, 0}}));
  // Writing to the pipe's read end fails (EBADF) with a message naming the target.
  try {
    writeInputEvents(fds[0], events, "test pipe");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("test pipe"), std::string::npos) << e.what();
  }
  ::close(fds[0]);
  ::close(fds[1]);
}

TEST(UinputJoystick, MissingOrWrongNodesGiveClearErrors) {
  std::string err = openError("/nonexistent/uinput");
  EXPECT_NE(err.find("/nonexistent/uinput"), std::string::npos) << err;
  EXPECT_NE(err.find("does not exist"), std::string::npos) << err;
  EXPECT_NE(err.find("modprobe uinput"), std::string::npos) << err;

  testing::ScratchDir scratch;
  const auto file = scratch.path() / "not-uinput.txt";
  { std::ofstream(file) << "x"; }
  err = openError(file.string());
  EXPECT_NE(err.find("not a character device"), std::string::npos) << err;

  err = openError("/dev/null");  // a character device, but not uinput
  EXPECT_NE(err.find("/dev/null"), std::string::npos) << err;
  EXPECT_NE(err.find("not a uinput device"), std::string::npos) << err;

  if (!std::filesystem::exists("/dev/uinput")) {  // this machine's kernel
    err = openError("/dev/uinput");
    EXPECT_NE(err.find("'/dev/uinput': does not exist"), std::string::npos) << err;
  }
}

TEST(UinputJoystick, PublishWithoutADeviceIsHarmless) {
  UinputJoystick j(UinputJoystickOptions{});
  EXPECT_FALSE(j.isOpen());
  j.publish(event(EventType::press));
  EXPECT_EQ(j.sysfsPath(), "");
}

}  // namespace
}  // namespace onetip::os_outputs
