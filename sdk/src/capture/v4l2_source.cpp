#include "capture/v4l2_source.hpp"

#include <linux/videodev2.h>
#include <sys/mman.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "capture/raw_decode.hpp"
#include "core/error.hpp"

namespace onetip::capture {

namespace {

// A failed step of start(), with the errno text.
struct DeviceFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string errnoText(const char* what) { return std::string(what) + ": " + std::strerror(errno); }

}  // namespace

void V4l2SourceOptions::validate() const {
  format.validate();
  if (buffer_count < 2 || buffer_count > 32)
    throw InputError("v4l2: buffer_count: must be between 2 and 32");
  if (frame_timeout_ms < 1) throw InputError("v4l2: frame_timeout_ms: must be positive");
  if (!(reconnect_interval_s >= 0.0) || !std::isfinite(reconnect_interval_s))
    throw InputError("v4l2: reconnect_interval_s: must be a non-negative number");
  if (max_reconnect_attempts < 1)
    throw InputError("v4l2: max_reconnect_attempts: must be at least 1");
}

V4l2Source::V4l2Source(std::string device, V4l2SourceOptions options, std::shared_ptr<V4l2Io> io)
    : device_(std::move(device)), options_(std::move(options)), io_(std::move(io)),
      checker_(FrameCheckOptions{{0, 0}, options_.min_stddev}) {
  options_.validate();
  if (device_.empty()) throw InputError("input 'v4l2:': no device path given");
  try {
    start();
  } catch (const DeviceFailure& e) {
    throw InputError("input 'v4l2:" + device_ + "': " + e.what());
  }
}

V4l2Source::~V4l2Source() { stop(); }

void V4l2Source::start() {
  fd_ = io_->open(device_);
  if (fd_ < 0) throw DeviceFailure(errnoText("cannot open the device"));
  try {
    v4l2_capability cap{};
    if (io_->ioctl(fd_, VIDIOC_QUERYCAP, &cap) != 0)
      throw DeviceFailure(errnoText("not a V4L2 device (VIDIOC_QUERYCAP)"));
    const std::uint32_t caps =
        (cap.capabilities & V4L2_CAP_DEVICE_CAPS) ? cap.device_caps : cap.capabilities;
    if (!(caps & V4L2_CAP_VIDEO_CAPTURE)) throw DeviceFailure("not a video capture device");
    if (!(caps & V4L2_CAP_STREAMING)) throw DeviceFailure("the device does not support streaming");

    const auto offers = enumerateV4l2Formats(*io_, fd_, options_.format);
    const auto choice = chooseV4l2Format(offers, options_.format);
    if (!choice) throw DeviceFailure("the device offers none of MJPEG, YUYV, GREY");
    format_ = *choice;

    v4l2_format fmt{};
    fmt.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    fmt.fmt.pix.width = static_cast<std::uint32_t>(format_.width);
    fmt.fmt.pix.height = static_cast<std::uint32_t>(format_.height);
    fmt.fmt.pix.pixelformat = format_.fourcc;
    fmt.fmt.pix.field = V4L2_FIELD_ANY;
    if (io_->ioctl(fd_, VIDIOC_S_FMT, &fmt) != 0) throw DeviceFailure(errnoText("VIDIOC_S_FMT"));
    if (fmt.fmt.pix.pixelformat != format_.fourcc ||
        static_cast<int>(fmt.fmt.pix.width) != format_.width ||
        static_cast<int>(fmt.fmt.pix.height) != format_.height)
      throw DeviceFailure("the driver changed the requested format " + fourccName(format_.fourcc) +
                          " " + std::to_string(format_.width) + "x" +
                          std::to_string(format_.height));
    const std::size_t min_line =
        static_cast<std::size_t>(format_.width) * (format_.fourcc == V4L2_PIX_FMT_YUYV ? 2 : 1);
    bytes_per_line_ = std::max<std::size_t>(fmt.fmt.pix.bytesperline, min_line);

    v4l2_streamparm parm{};  // the rate is a wish: drivers may ignore S_PARM
    parm.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    parm.parm.capture.timeperframe.numerator = format_.interval_num;
    parm.parm.capture.timeperframe.denominator = format_.interval_den;
    io_->ioctl(fd_, VIDIOC_S_PARM, &parm);

    v4l2_requestbuffers req{};
    req.count = static_cast<std::uint32_t>(options_.buffer_count);
    req.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    req.memory = V4L2_MEMORY_MMAP;
    if (io_->ioctl(fd_, VIDIOC_REQBUFS, &req) != 0) throw DeviceFailure(errnoText("VIDIOC_REQBUFS"));
    if (req.count < 2) throw DeviceFailure("the driver granted fewer than 2 buffers");
    for (std::uint32_t i = 0; i < req.count; ++i) {
      v4l2_buffer buf{};
      buf.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
      buf.memory = V4L2_MEMORY_MMAP;
      buf.index = i;
      if (io_->ioctl(fd_, VIDIOC_QUERYBUF, &buf) != 0)
        throw DeviceFailure(errnoText("VIDIOC_QUERYBUF"));
      void* p = io_->mmap(buf.length, fd_, static_cast<off_t>(buf.m.offset));
      if (p == MAP_FAILED) throw DeviceFailure(errnoText("mmap"));
      buffers_.push_back({p, buf.length});
      if (io_->ioctl(fd_, VIDIOC_QBUF, &buf) != 0) throw DeviceFailure(errnoText("VIDIOC_QBUF"));
    }
    int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    if (io_->ioctl(fd_, VIDIOC_STREAMON, &type) != 0)
      throw DeviceFailure(errnoText("VIDIOC_STREAMON"));
    streaming_on_ = true;
  } catch (...) {
    stop();
    throw;
  }
  checker_ = FrameChecker(FrameCheckOptions{{format_.width, format_.height}, options_.min_stddev});
}

void V4l2Source::stop() noexcept {
  if (fd_ < 0) return;
  if (streaming_on_) {
    int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    io_->ioctl(fd_, VIDIOC_STREAMOFF, &type);
    streaming_on_ = false;
  }
  for (const auto& b : buffers_) io_->munmap(b.start, b.length);
  if (!buffers_.empty()) {
    v4l2_requestbuffers req{};
    req.count = 0;
    req.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    req.memory = V4L2_MEMORY_MMAP;
    io_->ioctl(fd_, VIDIOC_REQBUFS, &req);
    buffers_.clear();
  }
  io_->close(fd_);
  fd_ = -1;
}

Frame V4l2Source::next() {
  if (ended_) return Frame{};
  return fd_ >= 0 ? capture() : reconnect();
}

Frame V4l2Source::deviceLost(const std::string& why) {
  stop();
  failed_attempts_ = 0;
  next_attempt_ = std::chrono::steady_clock::now();
  Frame f;
  f.status = FrameStatus::error;
  f.index = index_;
  f.message = "v4l2:" + device_ + ": " + why + "; reconnecting";
  return count(std::move(f));
}

Frame V4l2Source::reconnect() {
  std::this_thread::sleep_until(next_attempt_);
  Frame f;
  f.index = index_;
  try {
    start();
    failed_attempts_ = 0;
    return capture();
  } catch (const DeviceFailure& e) {
    ++failed_attempts_;
    next_attempt_ = std::chrono::steady_clock::now() +
                    std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                        std::chrono::duration<double>(options_.reconnect_interval_s));
    if (failed_attempts_ >= options_.max_reconnect_attempts) {
      ended_ = true;
      f.status = FrameStatus::end;
      f.message = "v4l2:" + device_ + ": gave up after " + std::to_string(failed_attempts_) +
                  " reconnection attempts (" + e.what() + ")";
      return f;
    }
    f.status = FrameStatus::error;
    f.message = "v4l2:" + device_ + ": reconnection attempt " + std::to_string(failed_attempts_) +
                " failed: " + e.what();
    return count(std::move(f));
  }
}

Frame V4l2Source::capture() {
  v4l2_buffer buf{};
  buf.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  buf.memory = V4L2_MEMORY_MMAP;
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::milliseconds(options_.frame_timeout_ms);
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0)
      return deviceLost("no frame within " + std::to_string(options_.frame_timeout_ms) + " ms");
    short revents = 0;
    const int ready = io_->poll(fd_, static_cast<int>(left.count()), revents);
    if (ready < 0) return deviceLost(errnoText("poll"));
    if (ready == 0) continue;  // the loop re-checks the deadline
    if (io_->ioctl(fd_, VIDIOC_DQBUF, &buf) == 0) break;
    if (errno != EAGAIN) return deviceLost(errnoText("camera lost (VIDIOC_DQBUF)"));
  }
  if (buf.index >= buffers_.size()) return deviceLost("the driver returned an unknown buffer");

  Frame f;
  f.index = index_++;
  f.timestamp_s = static_cast<double>(buf.timestamp.tv_sec) +
                  1e-6 * static_cast<double>(buf.timestamp.tv_usec);
  cv::Mat grey;
  const DecodeResult decoded =
      (buf.flags & V4L2_BUF_FLAG_ERROR)
          ? DecodeResult{false, "the driver flagged the frame as corrupted"}
          : decode(static_cast<const std::uint8_t*>(buffers_[buf.index].start),
                   std::min<std::size_t>(buf.bytesused, buffers_[buf.index].length), grey);
  if (decoded.ok && keep_encoded_) {
    const auto* data = static_cast<const std::uint8_t*>(buffers_[buf.index].start);
    f.encoded.assign(data, data + std::min<std::size_t>(buf.bytesused, buffers_[buf.index].length));
  }
  if (io_->ioctl(fd_, VIDIOC_QBUF, &buf) != 0)
    return deviceLost(errnoText("camera lost (VIDIOC_QBUF)"));
  const auto problem = decoded.ok ? checker_.problem(grey) : decoded.message;
  const std::string where = "frame " + std::to_string(f.index);
  return deliver(std::move(f), std::move(grey), problem, where);
}

bool V4l2Source::keepEncodedFrames(bool on) {
  keep_encoded_ = on && format_.fourcc == V4L2_PIX_FMT_MJPEG;
  return keep_encoded_ || !on;
}

DecodeResult V4l2Source::decode(const std::uint8_t* data, std::size_t bytes, cv::Mat& grey) {
  switch (format_.fourcc) {
    case V4L2_PIX_FMT_MJPEG:
      return jpeg_.decode(data, bytes, {format_.width, format_.height}, grey);
    case V4L2_PIX_FMT_YUYV:
      return yuyvToGrey(data, bytes, format_.width, format_.height, bytes_per_line_, grey);
    default:
      return greyToGrey(data, bytes, format_.width, format_.height, bytes_per_line_, grey);
  }
}

}  // namespace onetip::capture
