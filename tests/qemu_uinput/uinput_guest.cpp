// Runs inside the qemu guest (run_qemu_uinput.sh): creates the virtual
// joystick through onetip's UinputJoystick, reads it back through libevdev
// from /dev/input/eventN, publishes a fixed sequence of pipeline events and
// prints what the kernel delivers, then asks udev's input_id builtin how it
// classifies the device. Every line it prints starts with "ONETIP "; the host
// checks them with check_guest_output.py against its own computation.
//
//   uinput_guest                   the full check (uinput loaded)
//   uinput_guest --expect-missing  only open() with uinput not loaded: prints the error
#include <libevdev/libevdev.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

#include "core/error.hpp"
#include "os_outputs/uinput_joystick.hpp"

namespace {

using onetip::Input6;
using onetip::input::EventType;
using onetip::input::InputEvent;
using onetip::os_outputs::UinputJoystick;
using onetip::os_outputs::UinputJoystickOptions;

std::string eventNodeOf(const std::string& sysfs) {
  for (int attempt = 0; attempt < 200; ++attempt) {
    if (DIR* d = ::opendir(sysfs.c_str())) {
      std::string found;
      while (const dirent* e = ::readdir(d)) {
        if (std::strncmp(e->d_name, "event", 5) == 0) found = e->d_name;
      }
      ::closedir(d);
      if (!found.empty() && ::access(("/dev/input/" + found).c_str(), R_OK) == 0) return found;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return {};
}

void describe(libevdev* dev) {
  std::printf("ONETIP DEVICE name=%s bustype=%d vendor=%d product=%d\n", libevdev_get_name(dev),
              libevdev_get_id_bustype(dev), libevdev_get_id_vendor(dev), libevdev_get_id_product(dev));
  for (unsigned p = 0; p <= INPUT_PROP_MAX; ++p) {
    if (libevdev_has_property(dev, p)) std::printf("ONETIP PROP %u\n", p);
  }
  for (unsigned code = 0; code <= KEY_MAX; ++code) {
    if (libevdev_has_event_code(dev, EV_KEY, code)) std::printf("ONETIP KEY %u\n", code);
  }
  for (unsigned code = 0; code <= ABS_MAX; ++code) {
    if (!libevdev_has_event_code(dev, EV_ABS, code)) continue;
    const input_absinfo* a = libevdev_get_abs_info(dev, code);
    std::printf("ONETIP ABS %u %d %d %d %d %d\n", code, a->minimum, a->maximum, a->value, a->fuzz, a->flat);
  }
}

void drain(libevdev* dev) {
  input_event ev{};
  int rc;
  while ((rc = libevdev_next_event(dev, LIBEVDEV_READ_FLAG_NORMAL, &ev)) == LIBEVDEV_READ_STATUS_SUCCESS) {
    std::printf("ONETIP EVENT %d %d %d\n", ev.type, ev.code, ev.value);
  }
  if (rc != -EAGAIN) std::printf("ONETIP ERROR libevdev_next_event: %s\n", std::strerror(-rc));
}

InputEvent make(EventType type, double t, Input6 in = {}) {
  InputEvent e;
  e.type = type;
  e.t = t;
  e.input = in;
  return e;
}

int runCheck() {
  UinputJoystick joystick{UinputJoystickOptions{}};
  joystick.open();
  const std::string sysfs = joystick.sysfsPath();
  const std::string node = eventNodeOf(sysfs);
  if (node.empty()) {
    std::printf("ONETIP ERROR no event node under %s\n", sysfs.c_str());
    return 1;
  }
  std::printf("ONETIP SYSFS %s /dev/input/%s\n", sysfs.c_str(), node.c_str());
  const int fd = ::open(("/dev/input/" + node).c_str(), O_RDONLY | O_NONBLOCK);
  libevdev* dev = nullptr;
  if (fd < 0 || libevdev_new_from_fd(fd, &dev) < 0) {
    std::printf("ONETIP ERROR cannot read /dev/input/%s through libevdev\n", node.c_str());
    return 1;
  }
  describe(dev);

  Input6 a;
  a.dx = 1, a.dy = -2, a.dz = 1.5, a.yaw = 7.5, a.pitch = 20, a.roll = -10;
  Input6 beyond;
  beyond.dx = 9, beyond.dy = 0.5, beyond.dz = 4, beyond.yaw = -30, beyond.pitch = -50, beyond.roll = 39;
  const std::vector<InputEvent> script = {
      make(EventType::contact_begin, 0.0), make(EventType::input, 0.0, a),      make(EventType::press, 0.01),
      make(EventType::input, 0.02, beyond), make(EventType::release, 0.03), make(EventType::input, 0.04, a),
      make(EventType::contact_end, 0.05)};
  for (const InputEvent& e : script) {
    const Input6& v = e.input;
    std::printf("ONETIP PUBLISH %s %.6f %.6f %.6f %.6f %.6f %.6f\n", std::string(toString(e.type)).c_str(), v.dx,
                v.dy, v.dz, v.yaw, v.pitch, v.roll);
    joystick.publish(e);
    drain(dev);
  }
  for (unsigned code = ABS_X; code <= ABS_RZ; ++code) {
    std::printf("ONETIP FINAL %u %d\n", code, libevdev_get_event_value(dev, EV_ABS, code));
  }
  std::fflush(stdout);

  const std::string udev = "udevadm test-builtin input_id /sys/class/input/" + node + " 2>&1";
  if (FILE* p = ::popen(udev.c_str(), "r")) {
    char line[512];
    while (std::fgets(line, sizeof(line), p)) std::printf("ONETIP UDEV %s", line);
    std::printf("ONETIP UDEV-EXIT %d\n", ::pclose(p));
  }
  libevdev_free(dev);
  ::close(fd);
  joystick.close();
  std::printf("ONETIP DONE\n");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  const bool expect_missing = argc > 1 && std::strcmp(argv[1], "--expect-missing") == 0;
  try {
    if (expect_missing) {
      UinputJoystick joystick{UinputJoystickOptions{}};
      joystick.open();
      std::printf("ONETIP MISSING-ERROR none\n");
      return 1;
    }
    return runCheck();
  } catch (const onetip::InputError& e) {
    std::printf("ONETIP %s %s\n", expect_missing ? "MISSING-ERROR" : "ERROR", e.what());
    return expect_missing ? 0 : 1;
  } catch (const std::exception& e) {
    std::printf("ONETIP ERROR %s\n", e.what());
    return 1;
  }
}
