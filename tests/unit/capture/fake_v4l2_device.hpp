// A simulated V4L2 camera behind the V4l2Io interface, for testing
// V4l2Source without hardware. It implements the ioctls V4l2Source uses
// (QUERYCAP, ENUM_FMT, ENUM_FRAMESIZES, ENUM_FRAMEINTERVALS, S_FMT, S_PARM,
// REQBUFS, QUERYBUF, QBUF, DQBUF, STREAMON, STREAMOFF) with the kernel's
// errno conventions, hands out the queued payloads one per DQBUF, and can be
// unplugged and plugged back in. It records what was opened, mapped and
// streamed so tests can check for a clean stop.
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <string>
#include <vector>

#include "capture/v4l2_io.hpp"

namespace onetip::capture::testing {

struct FakeMode {
  std::uint32_t fourcc;
  int width, height;
  std::vector<std::uint32_t> fps;  // discrete rates offered (interval 1/fps)
};

struct FakePayload {
  std::vector<std::uint8_t> bytes;
  std::uint32_t flags = 0;  // e.g. V4L2_BUF_FLAG_ERROR
  double timestamp_s = 0.0;
};

class FakeV4l2Device final : public V4l2Io {
 public:
  // Set up by the test.
  std::vector<FakeMode> modes;
  std::uint32_t capabilities = 0;  // default: capture + streaming
  std::size_t line_padding = 0;    // extra bytes per line reported in bytesperline
  bool present = true;             // false: unplugged (open fails, DQBUF gives ENODEV)
  std::deque<FakePayload> payloads;

  // Observed.
  int open_count = 0, close_count = 0, mapped = 0, streamon_count = 0;
  bool streaming = false;
  std::uint32_t set_fourcc = 0;
  int set_width = 0, set_height = 0;
  std::uint32_t set_interval_den = 0;
  std::size_t bytesperline = 0;

  FakeV4l2Device();
  int open(const std::string& path) override;
  int close(int fd) override;
  int ioctl(int fd, unsigned long request, void* arg) override;
  void* mmap(std::size_t length, int fd, off_t offset) override;
  int munmap(void* address, std::size_t length) override;
  int poll(int fd, int timeout_ms, short& revents) override;

  bool openFd() const noexcept { return fd_open_; }

 private:
  std::vector<std::uint32_t> fourccs() const;
  const FakeMode* findMode(std::uint32_t fourcc, int w, int h) const;
  bool fd_open_ = false;
  std::vector<std::vector<std::uint8_t>> buffers_;
  std::deque<std::uint32_t> queued_;
};

}  // namespace onetip::capture::testing
