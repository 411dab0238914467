#include "vision/view_split.hpp"

#include <string>

#include "core/error.hpp"

namespace onetip::vision {

cv::Point2f ViewHalf::toView(cv::Point2f raw_pt) const noexcept {
  if (!flipped) return raw_pt;
  return {static_cast<float>(raw.cols - 1) - raw_pt.x, raw_pt.y};
}

void ViewHalf::toViewInPlace(std::vector<cv::Point2f>& pts) const noexcept {
  for (auto& p : pts) p = toView(p);
}

StereoViews splitViews(const cv::Mat& frame, const StereoCalibration& calib) {
  if (frame.empty()) throw InputError("frame: empty image");
  if (frame.type() != CV_8UC1) throw InputError("frame: expected 8-bit grey (CV_8UC1)");
  if (frame.cols != calib.image_width || frame.rows != calib.image_height) {
    throw InputError("frame: size " + std::to_string(frame.cols) + "x" + std::to_string(frame.rows) +
                     " differs from the calibration's " + std::to_string(calib.image_width) + "x" +
                     std::to_string(calib.image_height));
  }
  if (calib.split_x <= 0 || calib.split_x >= frame.cols) {
    throw InputError("calibration: split_x " + std::to_string(calib.split_x) + " outside the frame");
  }
  StereoViews views;
  views.left.raw = frame(cv::Rect(0, 0, calib.split_x, frame.rows));
  views.left.flipped = calib.flip_left;
  views.right.raw = frame(cv::Rect(calib.split_x, 0, frame.cols - calib.split_x, frame.rows));
  views.right.flipped = calib.flip_right;
  return views;
}

}  // namespace onetip::vision
