#include "os_outputs/uinput_joystick.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/error.hpp"

namespace onetip::os_outputs {

namespace {

std::string describeNode(const std::string& path) { return "uinput device '" + path + "'"; }

std::string openFailure(const std::string& path, int err) {
  switch (err) {
    case ENOENT:
      return describeNode(path) + ": does not exist (this kernel has no uinput: load it with `modprobe uinput`)";
    case EACCES:
    case EPERM:
      return describeNode(path) + ": permission denied (needs write access: a udev rule or the `input` group)";
    default:
      return describeNode(path) + ": cannot open: " + std::strerror(err);
  }
}

void checkedIoctl(int fd, unsigned long request, long arg, const std::string& path, const char* what) {
  if (::ioctl(fd, request, arg) < 0) {
    const int err = errno;
    if (err == ENOTTY || err == EINVAL) throw InputError(describeNode(path) + ": is not a uinput device (" + what + ")");
    throw InputError(describeNode(path) + ": " + what + ": " + std::strerror(err));
  }
}

void checkedIoctlWith(int fd, unsigned long request, const void* arg, const std::string& path, const char* what) {
  checkedIoctl(fd, request, reinterpret_cast<long>(arg), path, what);
}

}  // namespace

void UinputJoystickOptions::validate() const {
  if (node.empty()) throw InputError("joystick options: node: must not be empty");
  device.validate();
}

void writeInputEvents(int fd, std::span<const input_event> events, const std::string& what) {
  if (events.empty()) return;
  const size_t bytes = events.size_bytes();
  ssize_t n;
  do {
    n = ::write(fd, events.data(), bytes);
  } while (n < 0 && errno == EINTR);
  if (n < 0) throw std::runtime_error(what + ": write failed: " + std::strerror(errno));
  if (static_cast<size_t>(n) != bytes) throw std::runtime_error(what + ": short write");
}

UinputJoystick::UinputJoystick(UinputJoystickOptions options)
    : options_(std::move(options)), encoder_(options_.device.range) {}

UinputJoystick::~UinputJoystick() { close(); }

void UinputJoystick::open() {
  if (fd_ >= 0) return;
  options_.validate();
  const JoystickDescription d = describeJoystick(options_.device);
  const std::string& path = options_.node;
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !S_ISCHR(st.st_mode)) {
    throw InputError(describeNode(path) + ": is not a character device");
  }
  const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw InputError(openFailure(path, errno));
  try {
    checkedIoctl(fd, UI_SET_EVBIT, EV_SYN, path, "UI_SET_EVBIT");
    checkedIoctl(fd, UI_SET_EVBIT, EV_KEY, path, "UI_SET_EVBIT");
    checkedIoctl(fd, UI_SET_EVBIT, EV_ABS, path, "UI_SET_EVBIT");
    for (int key : d.keys) checkedIoctl(fd, UI_SET_KEYBIT, key, path, "UI_SET_KEYBIT");
    for (const uinput_abs_setup& axis : d.axes) {
      checkedIoctl(fd, UI_SET_ABSBIT, axis.code, path, "UI_SET_ABSBIT");
      checkedIoctlWith(fd, UI_ABS_SETUP, &axis, path, "UI_ABS_SETUP");
    }
    checkedIoctlWith(fd, UI_DEV_SETUP, &d.setup, path, "UI_DEV_SETUP");
    checkedIoctl(fd, UI_DEV_CREATE, 0L, path, "UI_DEV_CREATE");
  } catch (...) {
    ::close(fd);
    throw;
  }
  std::lock_guard lock(mutex_);
  encoder_ = JoystickEncoder(options_.device.range);
  fd_ = fd;
}

void UinputJoystick::close() noexcept {
  std::lock_guard lock(mutex_);
  if (fd_ < 0) return;
  ::ioctl(fd_, UI_DEV_DESTROY);
  ::close(fd_);
  fd_ = -1;
}

void UinputJoystick::publish(const input::InputEvent& event) {
  std::lock_guard lock(mutex_);
  if (fd_ < 0) return;
  const auto events = encoder_.onEvent(event);
  writeInputEvents(fd_, events, describeNode(options_.node));
}

std::string UinputJoystick::sysfsPath() const {
  if (fd_ < 0) return {};
  char name[64] = {};
  if (::ioctl(fd_, UI_GET_SYSNAME(sizeof(name) - 1), name) < 0) return {};
  return std::string("/sys/devices/virtual/input/") + name;
}

}  // namespace onetip::os_outputs
