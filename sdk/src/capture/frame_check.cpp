#include "capture/frame_check.hpp"

#include <cmath>

#include "core/error.hpp"

namespace onetip::capture {

void FrameCheckOptions::validate() const {
  if (expected_size.width < 0 || expected_size.height < 0 ||
      (expected_size.width == 0) != (expected_size.height == 0))
    throw InputError("frame check: expected_size: both sides positive, or both 0");
  if (!(min_stddev >= 0.0) || !std::isfinite(min_stddev))
    throw InputError("frame check: min_stddev: must be a non-negative number");
}

FrameChecker::FrameChecker(FrameCheckOptions options) : options_(options) { options_.validate(); }

std::optional<std::string> FrameChecker::problem(const cv::Mat& grey) {
  if (grey.empty()) return "empty frame (could not be decoded)";
  if (grey.type() != CV_8UC1) return "not an 8-bit grey frame";
  const cv::Size expected = options_.expected_size;
  if (expected.width > 0 && grey.size() != expected)
    return "wrong frame size " + std::to_string(grey.cols) + "x" + std::to_string(grey.rows) +
           " (expected " + std::to_string(expected.width) + "x" + std::to_string(expected.height) +
           ")";
  // Every 4th row: a strided header over the same pixels, no copy.
  const int sampled_rows = (grey.rows + 3) / 4;
  const cv::Mat sampled(sampled_rows, grey.cols, CV_8UC1, const_cast<uchar*>(grey.data),
                        grey.step[0] * 4);
  cv::Scalar mean, stddev;
  cv::meanStdDev(sampled, mean, stddev);
  if (stddev[0] < options_.min_stddev)
    return "blank frame (grey-level deviation " + std::to_string(stddev[0]).substr(0, 5) +
           " below " + std::to_string(options_.min_stddev).substr(0, 5) + ")";
  if (expected.width == 0) options_.expected_size = grey.size();
  return std::nullopt;
}

}  // namespace onetip::capture
