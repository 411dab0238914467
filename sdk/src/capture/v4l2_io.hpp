// capture/v4l2_io.hpp — the system calls a V4L2 camera needs, behind an
// interface so that the capture logic runs against a simulated device in
// tests (no camera exists on the build machines).
//
// Each call mirrors its POSIX counterpart: open/close/ioctl/munmap return -1
// and set errno on failure, mmap returns MAP_FAILED, poll returns > 0 when the
// descriptor is readable (or has an error condition, reported in `revents`),
// 0 on time-out.
#pragma once

#include <sys/types.h>

#include <cstddef>
#include <memory>
#include <string>

namespace onetip::capture {

class V4l2Io {
 public:
  virtual ~V4l2Io() = default;
  virtual int open(const std::string& path) = 0;  // read/write, non-blocking
  virtual int close(int fd) = 0;
  virtual int ioctl(int fd, unsigned long request, void* arg) = 0;
  virtual void* mmap(std::size_t length, int fd, off_t offset) = 0;
  virtual int munmap(void* address, std::size_t length) = 0;
  virtual int poll(int fd, int timeout_ms, short& revents) = 0;
};

// The real kernel interface (retries ioctl on EINTR).
std::shared_ptr<V4l2Io> systemV4l2Io();

}  // namespace onetip::capture
