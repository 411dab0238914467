#include "devices/serial_port.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>

#include "core/error.hpp"

namespace onetip::devices {
namespace {

speed_t speedOf(int baud) {
  switch (baud) {
    case 9600: return B9600;
    case 19200: return B19200;
    case 38400: return B38400;
    case 57600: return B57600;
    case 115200: return B115200;
    case 230400: return B230400;
    case 460800: return B460800;
    case 921600: return B921600;
    default: return B0;
  }
}

std::string errnoText() { return std::strerror(errno); }

}  // namespace

bool isSupportedBaud(int baud) {
  return std::find(std::begin(kSupportedBauds), std::end(kSupportedBauds), baud) != std::end(kSupportedBauds);
}

void SerialOptions::validate() const {
  if (port.empty()) throw InputError("SerialOptions.port: empty");
  if (!isSupportedBaud(baud)) {
    std::string rates;
    for (int b : kSupportedBauds) rates += (rates.empty() ? "" : ", ") + std::to_string(b);
    throw InputError("SerialOptions.baud: " + std::to_string(baud) + " is not a supported rate (" + rates + ")");
  }
  if (timeout_ms < 1 || timeout_ms > 10000) throw InputError("SerialOptions.timeout_ms: must be in [1, 10000]");
}

SerialPort::~SerialPort() { close(); }

void SerialPort::open(const SerialOptions& options) {
  options.validate();
  close();
  options_ = options;
  fd_ = openFd(true);
}

void SerialPort::reopen() {
  close();
  fd_ = openFd(false);
}

int SerialPort::openFd(bool as_input_error) {
  const std::string& path = options_.port;
  auto fail = [&](const std::string& why) -> int {
    if (as_input_error) throw InputError("port '" + path + "': " + why);
    throw LinkError("port '" + path + "': " + why);
  };
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return fail("no such device (" + errnoText() + ")");
  if (!S_ISCHR(st.st_mode)) return fail("not a character device");
  const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return fail("cannot open (" + errnoText() + ")");
  termios tio{};
  if (!::isatty(fd) || ::tcgetattr(fd, &tio) != 0) {
    ::close(fd);
    return fail("not a serial terminal");
  }
  ::cfmakeraw(&tio);
  tio.c_cflag |= CLOCAL | CREAD;
  tio.c_cflag &= ~static_cast<tcflag_t>(CRTSCTS | CSTOPB);
  tio.c_cc[VMIN] = 0;
  tio.c_cc[VTIME] = 0;
  const speed_t speed = speedOf(options_.baud);
  if (::cfsetispeed(&tio, speed) != 0 || ::cfsetospeed(&tio, speed) != 0 || ::tcsetattr(fd, TCSANOW, &tio) != 0) {
    const std::string why = errnoText();
    ::close(fd);
    return fail("cannot configure " + std::to_string(options_.baud) + " baud (" + why + ")");
  }
  ::tcflush(fd, TCIOFLUSH);
  return fd;
}

void SerialPort::close() noexcept {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

void SerialPort::write(std::span<const std::uint8_t> bytes) {
  if (fd_ < 0) throw LinkError("port '" + options_.port + "': not open");
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::milliseconds(options_.timeout_ms);
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
    if (n > 0) {
      done += static_cast<size_t>(n);
      continue;
    }
    if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)
      throw LinkError("port '" + options_.port + "': write failed (" + errnoText() + ")");
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    pollfd p{fd_, POLLOUT, 0};
    if (left <= 0 || ::poll(&p, 1, static_cast<int>(left)) <= 0)
      throw LinkError("port '" + options_.port + "': write timed out");
    if (p.revents & (POLLHUP | POLLERR | POLLNVAL)) throw LinkError("port '" + options_.port + "': hung up");
  }
}

std::vector<std::uint8_t> SerialPort::readAvailable(int timeout_ms) {
  if (fd_ < 0) throw LinkError("port '" + options_.port + "': not open");
  pollfd p{fd_, POLLIN, 0};
  const int ready = ::poll(&p, 1, std::max(0, timeout_ms));
  if (ready < 0 && errno != EINTR) throw LinkError("port '" + options_.port + "': poll failed (" + errnoText() + ")");
  if (ready <= 0) return {};
  if ((p.revents & POLLIN) == 0 && (p.revents & (POLLHUP | POLLERR | POLLNVAL)))
    throw LinkError("port '" + options_.port + "': hung up");
  std::vector<std::uint8_t> out(256);
  const ssize_t n = ::read(fd_, out.data(), out.size());
  if (n < 0) {
    if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) return {};
    throw LinkError("port '" + options_.port + "': read failed (" + errnoText() + ")");
  }
  if (n == 0) throw LinkError("port '" + options_.port + "': hung up");
  out.resize(static_cast<size_t>(n));
  return out;
}

std::vector<std::uint8_t> SerialPort::readExact(size_t n) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::milliseconds(options_.timeout_ms);
  std::vector<std::uint8_t> out;
  while (out.size() < n) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0)
      throw LinkError("port '" + options_.port + "': no reply within " + std::to_string(options_.timeout_ms) + " ms");
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(left)) <= 0) continue;
    if ((p.revents & POLLIN) == 0) throw LinkError("port '" + options_.port + "': hung up");
    std::uint8_t buf[64];
    const ssize_t got = ::read(fd_, buf, std::min(sizeof buf, n - out.size()));
    if (got < 0 && errno != EAGAIN && errno != EINTR)
      throw LinkError("port '" + options_.port + "': read failed (" + errnoText() + ")");
    if (got == 0) throw LinkError("port '" + options_.port + "': hung up");
    if (got > 0) out.insert(out.end(), buf, buf + got);
  }
  return out;
}

void SerialPort::flushInput() {
  if (fd_ >= 0) ::tcflush(fd_, TCIFLUSH);
}

}  // namespace onetip::devices
