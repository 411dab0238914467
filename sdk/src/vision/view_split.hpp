// vision/view_split.hpp — the two virtual views of one camera frame.
//
// A frame of image_width x image_height pixels holds the left view in columns
// [0, split_x) and the right view in [split_x, width) (docs/reference.md). A view
// is a cv::Mat ROI into the frame (no copy) plus its flip flag: when flipped,
// the view's own pixel coordinates are those of the half mirrored
// horizontally, x_view = w - 1 - x_raw (w = the half's width, y unchanged).
// The mapping is its own inverse. Detection runs on the raw (unflipped) half;
// its points are mapped to view coordinates before ids are assigned, so ids
// are anchored in the view after the flip. Units: pixels, pixel centres at
// integer coordinates.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "core/calibration.hpp"

namespace onetip::vision {

struct ViewHalf {
  cv::Mat raw;           // ROI into the frame, not mirrored
  bool flipped = false;  // the view is raw mirrored horizontally

  int width() const noexcept { return raw.cols; }
  int height() const noexcept { return raw.rows; }
  // Raw half pixel -> view pixel, and back (the same map).
  cv::Point2f toView(cv::Point2f raw_pt) const noexcept;
  cv::Point2f toRaw(cv::Point2f view_pt) const noexcept { return toView(view_pt); }
  void toViewInPlace(std::vector<cv::Point2f>& pts) const noexcept;
};

struct StereoViews {
  ViewHalf left;
  ViewHalf right;
};

// Splits an 8-bit single-channel frame. Throws InputError when the frame is
// empty, not CV_8UC1, or its size differs from the calibration's image size.
StereoViews splitViews(const cv::Mat& frame, const StereoCalibration& calib);

}  // namespace onetip::vision
