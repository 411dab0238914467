// os_outputs/uinput_joystick.hpp — a Linux virtual joystick through uinput:
// games (SDL, evdev/joydev readers) see the fingertip as six absolute axes and
// a trigger button. Device layout, scaling and the event rules:
// joystick_encoder.hpp and axis_scaling.hpp (x=dx, y=dy, z=dz, rx=pitch,
// ry=roll, rz=yaw; the working range maps to [-32767, 32767]).
//
// open() opens the uinput node (default /dev/uinput) and declares the device
// with UI_SET_EVBIT / UI_SET_KEYBIT / UI_SET_ABSBIT, UI_ABS_SETUP per axis,
// UI_DEV_SETUP and UI_DEV_CREATE. It throws InputError naming the node when it
// is missing (no uinput in this kernel: `modprobe uinput`), not accessible
// (permissions: udev rules or the `input` group) or not a uinput device.
// publish() writes the encoded events in one write() (nothing before open()
// or after close()); a failed write throws
// std::runtime_error naming the node. close() (and the destructor) destroys
// the device.
//
// Thread-safety: publish() and close() are serialised internally and may be
// called from any thread; open() and sysfsPath() from one controlling thread.
#pragma once

#include <mutex>
#include <span>
#include <string>

#include "input/input_event.hpp"
#include "os_outputs/joystick_encoder.hpp"

namespace onetip::os_outputs {

struct UinputJoystickOptions {
  std::string node = "/dev/uinput";
  JoystickDeviceOptions device;
  void validate() const;  // InputError naming the bad field
};

class UinputJoystick {
 public:
  explicit UinputJoystick(UinputJoystickOptions options);
  ~UinputJoystick();
  UinputJoystick(const UinputJoystick&) = delete;
  UinputJoystick& operator=(const UinputJoystick&) = delete;

  void open();
  void close() noexcept;
  bool isOpen() const noexcept { return fd_ >= 0; }

  void publish(const input::InputEvent& event);
  // The device's sysfs directory, e.g. /sys/devices/virtual/input/input7
  // (UI_GET_SYSNAME); empty when not open.
  std::string sysfsPath() const;
  const UinputJoystickOptions& options() const noexcept { return options_; }

 private:
  UinputJoystickOptions options_;
  JoystickEncoder encoder_;
  std::mutex mutex_;
  int fd_ = -1;
};

// Writes every event to fd in one write() (uinput accepts several at once);
// throws std::runtime_error naming `what` when the write fails or is short.
void writeInputEvents(int fd, std::span<const input_event> events, const std::string& what);

}  // namespace onetip::os_outputs
