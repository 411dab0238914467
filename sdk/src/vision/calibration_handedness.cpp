#include "vision/calibration_handedness.hpp"

#include <cstdio>

#include "core/error.hpp"
#include "vision/calibration_board.hpp"

namespace onetip::vision {

namespace {

double baselineX(const StereoCalibration& c) {
  // C_R = -R^T T, its x component in the left camera frame (mm).
  const cv::Vec3d centre = -(c.R.t() * c.T);
  return centre[0];
}

// The flag that mends a mirrored view: add it when absent, drop it when given.
std::string flagAdvice(const char* view, bool flipped) {
  return std::string(flipped ? "drop --flip-" : "add --flip-") + view;
}

std::string mm(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f mm", v);
  return text;
}

}  // namespace

HandednessCheck checkHandedness(const std::vector<BoardViewPair>& pairs, const MarkerPattern& pattern,
                                const StereoCalibration& layout, const StereoCalibrationOptions& options,
                                const StereoCalibrationResult& result, double max_rms_px) {
  HandednessCheck check;
  check.baseline_x_mm = baselineX(result.calibration);
  const bool agree = result.rms_px <= max_rms_px;
  if (!agree) {
    // Mirror every right view (x -> width - 1 - x, the flip's own map) and
    // number it again against the left view.
    StereoCalibration toggled = layout;
    toggled.flip_right = !layout.flip_right;
    const float last_x = static_cast<float>(layout.image_width - layout.split_x - 1);
    std::vector<BoardViewPair> mirrored;
    for (const auto& p : pairs) {
      std::vector<cv::Point2f> right = p.right;
      for (auto& q : right) q.x = last_x - q.x;
      mirrored.push_back({p.left, alignBoardNumbering(p.left, right, pattern.rows, pattern.cols)});
    }
    StereoCalibrationResult other;
    try {
      other = calibrateStereo(mirrored, pattern, toggled, options);
    } catch (const InputError&) {
      return check;  // no better fit: the residual has another cause
    }
    if (other.rms_px > max_rms_px) return check;
    // The views disagree. Mirroring the right one gave a consistent rig: if
    // its baseline points right the right view was the mirrored one,
    // otherwise both now are, and the left view was the mirrored one.
    if (baselineX(other.calibration) > 0)
      check.right_mirrored = true;
    else
      check.left_mirrored = true;
  } else if (check.baseline_x_mm < 0) {
    check.left_mirrored = check.right_mirrored = true;
  }
  if (check.left_mirrored && check.right_mirrored)
    check.problem = "both views are mirrored (the right view's camera lies " +
                    mm(-check.baseline_x_mm) + " to the left of the left view's): " +
                    flagAdvice("left", layout.flip_left) + " and " + flagAdvice("right", layout.flip_right);
  else if (check.left_mirrored || check.right_mirrored) {
    const char* view = check.left_mirrored ? "left" : "right";
    check.problem = std::string("the ") + view +
                    " view is mirrored (its board has the opposite handedness to the other view's, so no "
                    "stereo geometry fits both): " +
                    flagAdvice(view, check.left_mirrored ? layout.flip_left : layout.flip_right);
  }
  return check;
}

}  // namespace onetip::vision
