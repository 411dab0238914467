// capture/frame_check.hpp — is a decoded frame usable?
//
// Rejects, with a one-line reason, frames that are empty, not 8-bit grey,
// of a size other than the stream's (the expected size if one is given,
// otherwise the size of the first accepted frame), or blank: a frame whose
// grey-level standard deviation, estimated on every 4th row, is below
// min_stddev grey levels (a lens cap, a dead sensor, an all-black or
// all-white frame; sensor noise alone stays around 1-2 grey levels, an
// imaged checkerboard pad is far above).
#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <string>

namespace onetip::capture {

struct FrameCheckOptions {
  cv::Size expected_size{0, 0};  // {0, 0}: taken from the first accepted frame
  double min_stddev = 4.0;       // grey levels
  void validate() const;         // throws InputError naming the bad field
};

class FrameChecker {
 public:
  explicit FrameChecker(FrameCheckOptions options = {});
  // The reason the frame is unusable, or nullopt when it is fine. The first
  // accepted frame fixes the stream's size when none was expected.
  std::optional<std::string> problem(const cv::Mat& grey);
  // The stream's frame size: the expected one, or the first accepted frame's, or {0, 0}.
  cv::Size streamSize() const noexcept { return options_.expected_size; }

 private:
  FrameCheckOptions options_;
};

}  // namespace onetip::capture
