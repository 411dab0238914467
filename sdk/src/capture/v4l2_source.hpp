// capture/v4l2_source.hpp — frames from a V4L2 camera ("v4l2:/dev/videoN").
//
// Opens the device, checks it is a streaming video-capture device, picks a
// mode with chooseV4l2Format (1920x1080, highest rate; capture/v4l2_format.hpp),
// sets it (VIDIOC_S_FMT, VIDIOC_S_PARM), maps `buffer_count` driver buffers
// (VIDIOC_REQBUFS/QUERYBUF + mmap), queues them and starts streaming. next()
// waits at most frame_timeout_ms (poll), dequeues one buffer, decodes it to
// grey (MJPEG via TurboJPEG, YUYV luma, GREY copy), re-queues it, and stamps
// the frame with the driver's capture time (buffer timestamp, seconds on the
// clock the driver states, usually CLOCK_MONOTONIC).
// Failures never crash or hang: a buffer the driver flags as erroneous, a
// corrupt/truncated payload or a blank frame is a skipped frame; a vanished
// device (ENODEV, EIO, ...) or a time-out is an error event, after which the
// source stops, then tries to reopen and restart the stream once every
// reconnect_interval_s (each attempt another error event until it works), and
// ends after max_reconnect_attempts failed attempts in a row. The destructor
// stops streaming, unmaps and closes (clean stop).
#pragma once

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "capture/frame_check.hpp"
#include "capture/frame_source.hpp"
#include "capture/jpeg_grey_decoder.hpp"
#include "capture/v4l2_format.hpp"
#include "capture/v4l2_io.hpp"

namespace onetip::capture {

struct V4l2SourceOptions {
  V4l2FormatRequest format;
  int buffer_count = 4;
  int frame_timeout_ms = 2000;
  double reconnect_interval_s = 1.0;
  int max_reconnect_attempts = 30;
  double min_stddev = 4.0;  // blank-frame threshold, grey levels (frame_check.hpp)
  void validate() const;    // throws InputError naming the bad field
};

class V4l2Source : public FrameSource {
 public:
  // Throws InputError when the device cannot be opened, is not a streaming
  // capture device, or offers no decodable format.
  explicit V4l2Source(std::string device, V4l2SourceOptions options = {},
                      std::shared_ptr<V4l2Io> io = systemV4l2Io());
  ~V4l2Source() override;
  V4l2Source(const V4l2Source&) = delete;
  V4l2Source& operator=(const V4l2Source&) = delete;

  Frame next() override;
  std::string describe() const override { return "v4l2:" + device_; }
  // MJPEG modes only: each ok frame also carries the JPEG bytes as the driver delivered them.
  bool keepEncodedFrames(bool on) override;
  // The mode in use (valid after construction).
  const V4l2FormatOffer& format() const noexcept { return format_; }
  bool streaming() const noexcept { return fd_ >= 0; }

 private:
  struct MappedBuffer {
    void* start = nullptr;
    std::size_t length = 0;
  };
  void start();          // open, negotiate, map, stream on; throws on failure
  void stop() noexcept;  // stream off, unmap, release buffers, close
  Frame capture();       // one frame from the running stream
  Frame reconnect();     // one reconnection attempt
  Frame deviceLost(const std::string& why);
  DecodeResult decode(const std::uint8_t* data, std::size_t bytes, cv::Mat& grey);

  std::string device_;
  V4l2SourceOptions options_;
  std::shared_ptr<V4l2Io> io_;
  JpegGreyDecoder jpeg_;
  FrameChecker checker_;
  V4l2FormatOffer format_;
  std::size_t bytes_per_line_ = 0;
  int fd_ = -1;
  bool streaming_on_ = false;
  std::vector<MappedBuffer> buffers_;
  std::int64_t index_ = 0;
  int failed_attempts_ = 0;
  bool ended_ = false;
  bool keep_encoded_ = false;
  std::chrono::steady_clock::time_point next_attempt_{};
};

}  // namespace onetip::capture
