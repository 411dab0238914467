// os_outputs/joystick_encoder.hpp — the virtual joystick as data: the device
// it declares to uinput and the evdev events each pipeline event becomes. No
// I/O here; uinput_joystick.hpp applies and writes it.
//
// Device: EV_SYN, EV_KEY with one button BTN_TRIGGER (the press), EV_ABS with
// ABS_X, ABS_Y, ABS_Z, ABS_RX, ABS_RY, ABS_RZ = dx, dy, dz, pitch, roll, yaw
// (axis_scaling.hpp), each in [-32767, 32767], fuzz 0, flat 0, starting at
// the rest value. No input properties (in particular not
// INPUT_PROP_ACCELEROMETER). Why this is a joystick for udev's input_id and
// SDL: it has a key (so ABS_X/Y/Z are not taken for an accelerometer), a
// button in the BTN_JOYSTICK range and ABS_RX.., and no mouse button, touch
// or direct property that would make it a mouse, touchpad or touchscreen.
//
// Events: for each pipeline event, an EV_ABS for every axis whose value
// changed, an EV_KEY BTN_TRIGGER 1/0 for press/release, then one
// EV_SYN/SYN_REPORT; nothing at all when nothing changed. Contact end returns
// every axis to its rest value and releases the button (output_intent.hpp).
#pragma once

#include <array>
#include <linux/input.h>
#include <linux/uinput.h>
#include <string>
#include <vector>

#include "input/input_event.hpp"
#include "os_outputs/axis_scaling.hpp"
#include "os_outputs/output_intent.hpp"

namespace onetip::os_outputs {

inline constexpr int kJoystickButton = BTN_TRIGGER;
inline constexpr std::array<int, kAxisCount> kJoystickAxisCodes = {ABS_X, ABS_Y, ABS_Z, ABS_RX, ABS_RY, ABS_RZ};

struct JoystickDeviceOptions {
  std::string name = "onetip tactile joystick";  // 1..79 bytes (UINPUT_MAX_NAME_SIZE - 1)
  std::uint16_t vendor = 0x0000, product = 0x0000, version = 1;
  WorkingRange range;
  void validate() const;  // InputError naming the bad field
};

// What UI_DEV_SETUP, UI_ABS_SETUP and UI_SET_KEYBIT receive.
struct JoystickDescription {
  uinput_setup setup{};
  std::array<uinput_abs_setup, kAxisCount> axes{};
  std::vector<int> keys;
};
JoystickDescription describeJoystick(const JoystickDeviceOptions& options);

class JoystickEncoder {
 public:
  explicit JoystickEncoder(const WorkingRange& range);
  // The evdev events for one pipeline event (possibly none). Not thread-safe.
  std::vector<input_event> onEvent(const input::InputEvent& event);
  const std::array<std::int32_t, kAxisCount>& axes() const noexcept { return axes_; }
  bool buttonDown() const noexcept { return tracker_.buttonDown(); }

 private:
  WorkingRange range_;
  OutputTracker tracker_;
  std::array<std::int32_t, kAxisCount> axes_{};
};

}  // namespace onetip::os_outputs
