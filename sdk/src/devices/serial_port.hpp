// devices/serial_port.hpp — a raw serial line (termios) for the device drivers.
//
// The port is opened non-blocking, raw (cfmakeraw: 8 data bits, no parity, one
// stop bit, no echo, no flow control), with VMIN = VTIME = 0; reads and writes
// wait with poll() up to `timeout_ms`. Baud rates are validated against the
// termios rates the drivers support (kSupportedBauds). Errors:
//   - configuration (bad option, a port that does not exist or is not a
//     terminal) -> InputError at open(), naming the field or the port;
//   - a link that fails later (hang-up, EIO when the other side closes, a
//     write that cannot complete in time) -> LinkError; reopen() then tries
//     the same path again (a udev symlink, or a pty re-created behind it).
#pragma once

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace onetip::devices {

// Every baud rate the transport can set (bits per second).
inline constexpr int kSupportedBauds[] = {9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600};

bool isSupportedBaud(int baud);

// A failure of an open link (as opposed to a bad configuration).
class LinkError : public std::runtime_error {
 public:
  explicit LinkError(const std::string& message) : std::runtime_error(message) {}
};

struct SerialOptions {
  std::string port;      // e.g. /dev/ttyACM0
  int baud = 115200;     // one of kSupportedBauds
  int timeout_ms = 50;   // longest wait for one read or write, 1..10000
  void validate() const;  // throws InputError naming the bad field
};

class SerialPort {
 public:
  SerialPort() = default;
  ~SerialPort();
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  // Validates the options and opens the port; InputError when the options are
  // bad or the port is missing or not a terminal.
  void open(const SerialOptions& options);
  // Closes and opens the same path again; LinkError when that fails.
  void reopen();
  void close() noexcept;
  bool isOpen() const noexcept { return fd_ >= 0; }
  const SerialOptions& options() const noexcept { return options_; }

  // Writes every byte or throws LinkError.
  void write(std::span<const std::uint8_t> bytes);
  // Reads what arrives within timeout_ms (at least one byte when it returns
  // non-empty); LinkError when the line hangs up.
  std::vector<std::uint8_t> readAvailable(int timeout_ms);
  // Reads exactly n bytes or throws LinkError (timeout or hang-up).
  std::vector<std::uint8_t> readExact(size_t n);
  // Discards unread input.
  void flushInput();

 private:
  int openFd(bool as_input_error);
  SerialOptions options_;
  int fd_ = -1;
};

}  // namespace onetip::devices
