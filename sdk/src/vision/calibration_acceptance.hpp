// vision/calibration_acceptance.hpp — can a stereo calibration support the
// accuracy the SDK claims? The reasons to refuse one, each in one line.
//
// The claim (docs/vision/README.md): 3-D markers within about 0.001 mm of the
// truth with the calibration `onetip calibrate` makes, held by the tests to
// 0.03 mm. A calibration can break it two ways, and each threshold below is
// that 0.03 mm limit carried through the sensor's geometry:
//  - Misfit. A residual the lens model cannot explain (views not taken at the
//    same instant, a bent board, a mirrored view) is up to rms_px of error in
//    each view's rays. A disparity error of e px moves a point Z^2 / (f b) * e
//    along depth: on the sensor (Z = 28 mm, f = 1000 px, b = 24 mm; docs/sim)
//    0.033 mm per px, so 0.03 mm allows at most 0.9 px. Good calibrations sit
//    far below it: 0.057 px on the simulated set, 0.218 px on OpenCV's photos.
//  - Coverage. Too few poses, all at one tilt, leave the focal length free to
//    trade against the board's distance (Zhang 2000: each view of a plane
//    gives two constraints on the intrinsics; a pure shift adds none). The
//    single-view fits report one standard deviation of f from their residuals
//    and the poses' spread, so it measures exactly what the poses pin down.
//    An error df/f scales every depth, so a press at the end of the 3 mm
//    working range reads 3 mm * df/f off; 0.03 mm at three standard
//    deviations allows sd(f)/f <= 0.03 / (3 x 3) = 0.0033.
//    The tilt spread and the share of the view the corners cover are reported
//    beside it, as the things to improve when it is refused.
// A calibration with a mirrored view is refused too (calibration_handedness.hpp).
#pragma once

#include <string>
#include <vector>

#include "core/calibration.hpp"
#include "core/pattern.hpp"
#include "vision/stereo_calibration.hpp"

namespace onetip::vision {

struct CalibrationAcceptanceOptions {
  double max_rms_px = 0.9;            // px, (0, 10]: 0.03 mm / (0.033 mm of depth per px)
  double max_f_sd_fraction = 0.0033;  // sd(f)/f, (0, 1]: 0.03 mm / (3 sd x 3 mm working range)
  void validate() const;              // throws InputError naming the bad field
};

struct CalibrationCoverage {
  int poses = 0;                   // frames with the board in both views
  double tilt_spread_deg = 0.0;    // largest angle between two poses' board normals
  double view_fraction = 0.0;      // left view area inside the hull of all corners, 0..1
  double worst_f_sd_fraction = 0;  // largest sd(f)/f over fx, fy of both views
};

struct CalibrationVerdict {
  CalibrationCoverage coverage;
  double baseline_x_mm = 0.0;        // the right view's camera centre along the left camera's x
  std::vector<std::string> reasons;  // one line each; empty: accepted
};

CalibrationCoverage measureCoverage(const std::vector<BoardViewPair>& pairs,
                                    const StereoCalibration& layout,
                                    const StereoCalibrationResult& result);

// Every reason to refuse `result` (calibrateStereo of pairs with options).
CalibrationVerdict judgeCalibration(const std::vector<BoardViewPair>& pairs, const MarkerPattern& pattern,
                                    const StereoCalibration& layout, const StereoCalibrationOptions& options,
                                    const StereoCalibrationResult& result,
                                    const CalibrationAcceptanceOptions& acceptance = {});

}  // namespace onetip::vision
