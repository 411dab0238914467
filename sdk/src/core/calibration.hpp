// core/calibration.hpp — the virtual binocular calibration file (docs/reference.md).
//
// One camera frame of image_width x image_height holds both views side by
// side; the left view is columns [0, split_x), the right [split_x, width).
// flip_left/flip_right mirror a half horizontally before use (x' = w - 1 - x).
// Each view's pixel coordinates are those of its own half after the flip.
// K_*: 3x3 pinhole intrinsics (pixels); D_*: k1 k2 p1 p2 k3 (OpenCV model).
// R, T: right-from-left, X_R = R * X_L + T, T in millimetres.
#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace onetip {

struct StereoCalibration {
  int image_width = 1920;
  int image_height = 1080;
  int split_x = 960;
  bool flip_left = false;
  bool flip_right = false;
  cv::Matx33d K_left = cv::Matx33d::eye();
  cv::Matx33d K_right = cv::Matx33d::eye();
  cv::Vec<double, 5> D_left{0, 0, 0, 0, 0};
  cv::Vec<double, 5> D_right{0, 0, 0, 0, 0};
  cv::Matx33d R = cv::Matx33d::eye();
  cv::Vec3d T{0, 0, 0};

  int leftWidth() const noexcept { return split_x; }
  int rightWidth() const noexcept { return image_width - split_x; }

  // Throws InputError naming the first inconsistent field.
  void validate() const;
};

// Reads the calibration file; throws InputError naming a missing or bad key.
StereoCalibration loadCalibration(const std::string& path);
// Writes it atomically (no partial file on failure); extra scalar entries
// (e.g. "rms_px") are appended after the standard keys.
void saveCalibration(const StereoCalibration& calib, const std::string& path,
                     double rms_px = -1.0);

}  // namespace onetip
