#include "fake_v4l2_device.hpp"

#include <linux/videodev2.h>
#include <poll.h>
#include <sys/mman.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <thread>

namespace onetip::capture::testing {

namespace {
constexpr int kFd = 7;
constexpr off_t kOffsetStep = 1 << 24;
}  // namespace

FakeV4l2Device::FakeV4l2Device() : capabilities(V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING) {}

std::vector<std::uint32_t> FakeV4l2Device::fourccs() const {
  std::vector<std::uint32_t> out;
  for (const auto& m : modes)
    if (std::find(out.begin(), out.end(), m.fourcc) == out.end()) out.push_back(m.fourcc);
  return out;
}

const FakeMode* FakeV4l2Device::findMode(std::uint32_t fourcc, int w, int h) const {
  for (const auto& m : modes)
    if (m.fourcc == fourcc && m.width == w && m.height == h) return &m;
  return nullptr;
}

int FakeV4l2Device::open(const std::string&) {
  if (!present) {
    errno = ENOENT;
    return -1;
  }
  ++open_count;
  fd_open_ = true;
  return kFd;
}

int FakeV4l2Device::close(int fd) {
  if (fd != kFd || !fd_open_) {
    errno = EBADF;
    return -1;
  }
  ++close_count;
  fd_open_ = false;
  streaming = false;
  buffers_.clear();
  queued_.clear();
  return 0;
}

int FakeV4l2Device::ioctl(int fd, unsigned long request, void* arg) {
  if (fd != kFd || !fd_open_) {
    errno = EBADF;
    return -1;
  }
  if (!present) {
    errno = ENODEV;
    return -1;
  }
  const auto fail = [](int e) {
    errno = e;
    return -1;
  };
  switch (request) {
    case VIDIOC_QUERYCAP: {
      auto* cap = static_cast<v4l2_capability*>(arg);
      std::memset(cap, 0, sizeof(*cap));
      cap->capabilities = capabilities;
      return 0;
    }
    case VIDIOC_ENUM_FMT: {
      auto* d = static_cast<v4l2_fmtdesc*>(arg);
      const auto list = fourccs();
      if (d->index >= list.size()) return fail(EINVAL);
      d->pixelformat = list[d->index];
      return 0;
    }
    case VIDIOC_ENUM_FRAMESIZES: {
      auto* s = static_cast<v4l2_frmsizeenum*>(arg);
      std::uint32_t n = 0;
      for (const auto& m : modes)
        if (m.fourcc == s->pixel_format && n++ == s->index) {
          s->type = V4L2_FRMSIZE_TYPE_DISCRETE;
          s->discrete.width = static_cast<std::uint32_t>(m.width);
          s->discrete.height = static_cast<std::uint32_t>(m.height);
          return 0;
        }
      return fail(EINVAL);
    }
    case VIDIOC_ENUM_FRAMEINTERVALS: {
      auto* iv = static_cast<v4l2_frmivalenum*>(arg);
      const FakeMode* m = findMode(iv->pixel_format, static_cast<int>(iv->width),
                                   static_cast<int>(iv->height));
      if (m == nullptr || iv->index >= m->fps.size()) return fail(EINVAL);
      iv->type = V4L2_FRMIVAL_TYPE_DISCRETE;
      iv->discrete.numerator = 1;
      iv->discrete.denominator = m->fps[iv->index];
      return 0;
    }
    case VIDIOC_S_FMT: {
      auto* f = static_cast<v4l2_format*>(arg);
      if (streaming || !buffers_.empty()) return fail(EBUSY);
      const FakeMode* m = findMode(f->fmt.pix.pixelformat, static_cast<int>(f->fmt.pix.width),
                                   static_cast<int>(f->fmt.pix.height));
      if (m == nullptr) m = &modes.front();  // drivers adjust rather than refuse
      set_fourcc = m->fourcc;
      set_width = m->width;
      set_height = m->height;
      const std::size_t bpp = m->fourcc == V4L2_PIX_FMT_YUYV ? 2 : 1;
      bytesperline =
          m->fourcc == V4L2_PIX_FMT_MJPEG ? 0 : static_cast<std::size_t>(m->width) * bpp + line_padding;
      f->fmt.pix.pixelformat = m->fourcc;
      f->fmt.pix.width = static_cast<std::uint32_t>(m->width);
      f->fmt.pix.height = static_cast<std::uint32_t>(m->height);
      f->fmt.pix.bytesperline = static_cast<std::uint32_t>(bytesperline);
      f->fmt.pix.sizeimage = static_cast<std::uint32_t>(
          std::max<std::size_t>(bytesperline, static_cast<std::size_t>(m->width) * 2) *
          static_cast<std::size_t>(m->height));
      return 0;
    }
    case VIDIOC_S_PARM: {
      auto* p = static_cast<v4l2_streamparm*>(arg);
      set_interval_den = p->parm.capture.timeperframe.denominator;
      return 0;
    }
    case VIDIOC_REQBUFS: {
      auto* r = static_cast<v4l2_requestbuffers*>(arg);
      if (r->memory != V4L2_MEMORY_MMAP) return fail(EINVAL);
      if (streaming || mapped > 0) return fail(EBUSY);
      buffers_.assign(r->count, std::vector<std::uint8_t>(static_cast<std::size_t>(set_width) * 2 *
                                                          static_cast<std::size_t>(set_height) +
                                                          line_padding * static_cast<std::size_t>(set_height)));
      queued_.clear();
      return 0;
    }
    case VIDIOC_QUERYBUF: {
      auto* b = static_cast<v4l2_buffer*>(arg);
      if (b->index >= buffers_.size()) return fail(EINVAL);
      b->length = static_cast<std::uint32_t>(buffers_[b->index].size());
      b->m.offset = static_cast<std::uint32_t>(b->index * kOffsetStep);
      return 0;
    }
    case VIDIOC_QBUF: {
      auto* b = static_cast<v4l2_buffer*>(arg);
      if (b->index >= buffers_.size()) return fail(EINVAL);
      queued_.push_back(b->index);
      return 0;
    }
    case VIDIOC_DQBUF: {
      auto* b = static_cast<v4l2_buffer*>(arg);
      if (!streaming) return fail(EINVAL);
      if (queued_.empty() || payloads.empty()) return fail(EAGAIN);
      const std::uint32_t index = queued_.front();
      queued_.pop_front();
      FakePayload p = std::move(payloads.front());
      payloads.pop_front();
      auto& buf = buffers_[index];
      const std::size_t n = std::min(buf.size(), p.bytes.size());
      std::memcpy(buf.data(), p.bytes.data(), n);
      b->index = index;
      b->bytesused = static_cast<std::uint32_t>(n);
      b->flags = p.flags | V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC;
      b->timestamp.tv_sec = static_cast<time_t>(std::floor(p.timestamp_s));
      b->timestamp.tv_usec =
          static_cast<suseconds_t>(std::lround((p.timestamp_s - std::floor(p.timestamp_s)) * 1e6));
      return 0;
    }
    case VIDIOC_STREAMON:
      if (buffers_.empty()) return fail(EINVAL);
      streaming = true;
      ++streamon_count;
      return 0;
    case VIDIOC_STREAMOFF:
      streaming = false;
      queued_.clear();
      return 0;
    default:
      return fail(ENOTTY);
  }
}

void* FakeV4l2Device::mmap(std::size_t length, int fd, off_t offset) {
  const auto index = static_cast<std::size_t>(offset / kOffsetStep);
  if (fd != kFd || !fd_open_ || index >= buffers_.size() || length != buffers_[index].size()) {
    errno = EINVAL;
    return MAP_FAILED;
  }
  ++mapped;
  return buffers_[index].data();
}

int FakeV4l2Device::munmap(void*, std::size_t) {
  --mapped;
  return 0;
}

int FakeV4l2Device::poll(int fd, int timeout_ms, short& revents) {
  revents = 0;
  if (fd != kFd || !fd_open_) {
    errno = EBADF;
    return -1;
  }
  if (!present) {
    revents = POLLERR;
    return 1;
  }
  if (streaming && !payloads.empty() && !queued_.empty()) {
    revents = POLLIN;
    return 1;
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(timeout_ms));
  return 0;
}

}  // namespace onetip::capture::testing
