// capture/frame_source.hpp — where camera frames come from.
//
// A FrameSource hands out 8-bit single-channel (grey) frames one at a time.
// Every call to next() returns a Frame whose status says what happened:
//   ok       — `grey` holds the frame (CV_8UC1, row-major, origin top-left);
//   skipped  — this frame was unusable (corrupted, truncated, wrong size,
//              blank); `message` says why; the stream goes on;
//   error    — a device-level event (camera unplugged, time-out); the source
//              is trying to recover (e.g. reconnecting) and later calls may
//              return ok again;
//   end      — no more frames; further calls keep returning end.
// Sources never throw from next() for bad data; only construction with a bad
// specification throws InputError. `index` counts every frame the source
// produced or tried to produce (0-based, skipped ones included), so a
// skipped frame keeps its place in the numbering. `timestamp_s` is in
// seconds: the driver's capture time for cameras, the position for videos,
// index / nominal rate for image folders.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

namespace onetip::capture {

enum class FrameStatus : std::uint8_t { ok, skipped, error, end };

// "ok", "skipped", "error", "end".
const char* toString(FrameStatus s) noexcept;

struct Frame {
  FrameStatus status = FrameStatus::end;
  cv::Mat grey;              // CV_8UC1 when status == ok, empty otherwise
  std::int64_t index = -1;   // position in the stream (0-based)
  double timestamp_s = 0.0;
  std::string message;       // why, when status is skipped or error
  // The camera's compressed payload as delivered (MJPEG), when the source
  // keeps it (keepEncodedFrames); empty otherwise.
  std::vector<std::uint8_t> encoded;

  bool ok() const noexcept { return status == FrameStatus::ok; }
};

// Running totals of what a source delivered.
struct FrameCounters {
  std::int64_t delivered = 0;  // frames returned with status ok
  std::int64_t skipped = 0;    // frames returned with status skipped
  std::int64_t errors = 0;     // error events
};

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  // The next frame or event; never blocks longer than the source's stated
  // time-out and never throws for bad frame data.
  virtual Frame next() = 0;
  // Human-readable name of the source (e.g. the spec it was opened from).
  virtual std::string describe() const = 0;
  // Asks the source to fill Frame::encoded with each frame's compressed
  // payload (for recording without re-encoding); returns whether it can
  // (a camera delivering MJPEG can, decoded sources cannot).
  virtual bool keepEncodedFrames(bool /*on*/) { return false; }
  const FrameCounters& counters() const noexcept { return counters_; }

 protected:
  // Updates the counters from the frame's status and returns it.
  Frame count(Frame f);
  // Completes `f` (index and timestamp set) as ok with `grey`, or as skipped
  // with "<where>: <problem>" when there is a problem; counts it.
  Frame deliver(Frame f, cv::Mat grey, const std::optional<std::string>& problem,
                const std::string& where);

 private:
  FrameCounters counters_;
};

}  // namespace onetip::capture
