// capture/video_source.hpp — frames from a video file (cv::VideoCapture).
//
// Frames are converted to 8-bit grey. The timestamp is the container's
// presentation time (CAP_PROP_POS_MSEC / 1000) when it is known, otherwise
// index / the file's frame rate. Frames failing the FrameChecker are counted
// skipped; the end of the file (or a read failure after the last good frame)
// is end.
#pragma once

#include <opencv2/videoio.hpp>
#include <string>

#include "capture/frame_check.hpp"
#include "capture/frame_source.hpp"

namespace onetip::capture {

class VideoSource : public FrameSource {
 public:
  // Throws InputError when the file cannot be opened as a video.
  explicit VideoSource(const std::string& path, FrameCheckOptions check = {});
  Frame next() override;
  std::string describe() const override { return path_; }

 private:
  std::string path_;
  cv::VideoCapture video_;
  FrameChecker checker_;
  double rate_hz_ = 30.0;
  std::int64_t position_ = 0;
  bool ended_ = false;
};

}  // namespace onetip::capture
