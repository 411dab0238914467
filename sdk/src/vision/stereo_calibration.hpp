// vision/stereo_calibration.hpp — calibrating the two virtual cameras from
// views of a checkerboard target.
//
// Input: for every frame in which the whole board was found in both views,
// the board's corners in each view's pixel coordinates (after the flip,
// numbered row * cols + col as vision/calibration_board.hpp does). Object
// points are the board's corners in its own plane, (col, row, 0) x square_mm.
// 1. cv::calibrateCamera per view (k1 k2 p1 p2 k3, no constraints);
// 2. cv::stereoCalibrate from those intrinsics, either with
//    CALIB_FIX_INTRINSIC (R, T only) or, by default, CALIB_USE_INTRINSIC_GUESS
//    (refines intrinsics and R, T jointly; on OpenCV's real stereo set this
//    gives 0.218 px against 0.221 px with fixed intrinsics).
// The RMS is the stereo reprojection error over both views, in pixels. The
// single-view fits also give the standard deviation of each focal length as
// the fit estimates it (cv::calibrateCamera's stdDeviationsIntrinsics: the
// residual's variance through the inverse normal matrix), which is how far
// the poses' number and spread pin f down (vision/calibration_acceptance.hpp).
// R, T follow docs/reference.md (X_R = R X_L + T), T in mm.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/calibration.hpp"
#include "core/pattern.hpp"

namespace onetip::vision {

struct BoardViewPair {
  std::vector<cv::Point2f> left, right;  // pattern.count() corners each
};

struct StereoCalibrationOptions {
  bool refine_jointly = true;  // false: CALIB_FIX_INTRINSIC
  int min_pairs = 3;           // board pairs needed (each gives 1 pose)
  void validate() const;       // throws InputError naming the bad field
};

struct StereoCalibrationResult {
  StereoCalibration calibration;
  double rms_px = 0.0;        // stereo reprojection RMS, both views
  double rms_left_px = 0.0;   // single-view calibrations
  double rms_right_px = 0.0;
  int pairs_used = 0;
  // One standard deviation of fx, fy of each single-view fit (px); infinite
  // when the poses leave f undetermined (a singular normal matrix).
  cv::Vec2d sd_f_left{0, 0}, sd_f_right{0, 0};
  // The board's pose in the left camera per pair (Rodrigues vector, mm).
  std::vector<cv::Vec3d> board_rvecs, board_tvecs;
};

// layout supplies image_width, image_height, split_x and the flips; the view
// sizes follow from them. Throws InputError when fewer than min_pairs pairs
// are given, a pair has the wrong number of corners, or the fit fails.
StereoCalibrationResult calibrateStereo(const std::vector<BoardViewPair>& pairs,
                                        const MarkerPattern& pattern,
                                        const StereoCalibration& layout,
                                        const StereoCalibrationOptions& options = {});

}  // namespace onetip::vision
