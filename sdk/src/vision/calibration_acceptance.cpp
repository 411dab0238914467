#include "vision/calibration_acceptance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/option_checks.hpp"
#include "vision/calibration_handedness.hpp"

namespace onetip::vision {

namespace {

std::string fixed(double v, int digits) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", digits, v);
  return text;
}

}  // namespace

void CalibrationAcceptanceOptions::validate() const {
  requireInRange("calibration acceptance: max_rms_px", max_rms_px, 1e-6, 10.0, "px");
  requireInRange("calibration acceptance: max_f_sd_fraction", max_f_sd_fraction, 1e-9, 1.0);
}

CalibrationCoverage measureCoverage(const std::vector<BoardViewPair>& pairs,
                                    const StereoCalibration& layout,
                                    const StereoCalibrationResult& result) {
  CalibrationCoverage c;
  c.poses = static_cast<int>(pairs.size());
  std::vector<cv::Vec3d> normals;
  for (const auto& rvec : result.board_rvecs) {
    cv::Matx33d R;
    cv::Rodrigues(rvec, R);
    normals.emplace_back(R(0, 2), R(1, 2), R(2, 2));
  }
  for (size_t i = 0; i < normals.size(); ++i)
    for (size_t j = i + 1; j < normals.size(); ++j)
      c.tilt_spread_deg = std::max(
          c.tilt_spread_deg, std::acos(std::clamp(normals[i].dot(normals[j]), -1.0, 1.0)) * 180.0 / CV_PI);
  std::vector<cv::Point2f> all, hull;
  for (const auto& p : pairs) all.insert(all.end(), p.left.begin(), p.left.end());
  if (all.size() >= 3) {
    cv::convexHull(all, hull);
    c.view_fraction = cv::contourArea(hull) / (static_cast<double>(layout.split_x) * layout.image_height);
  }
  const cv::Matx33d& Kl = result.calibration.K_left;
  const cv::Matx33d& Kr = result.calibration.K_right;
  c.worst_f_sd_fraction = std::max({result.sd_f_left[0] / Kl(0, 0), result.sd_f_left[1] / Kl(1, 1),
                                    result.sd_f_right[0] / Kr(0, 0), result.sd_f_right[1] / Kr(1, 1)});
  return c;
}

CalibrationVerdict judgeCalibration(const std::vector<BoardViewPair>& pairs, const MarkerPattern& pattern,
                                    const StereoCalibration& layout, const StereoCalibrationOptions& options,
                                    const StereoCalibrationResult& result,
                                    const CalibrationAcceptanceOptions& acceptance) {
  acceptance.validate();
  CalibrationVerdict v;
  v.coverage = measureCoverage(pairs, layout, result);
  const HandednessCheck handedness =
      checkHandedness(pairs, pattern, layout, options, result, acceptance.max_rms_px);
  v.baseline_x_mm = handedness.baseline_x_mm;
  if (!handedness.problem.empty()) v.reasons.push_back(handedness.problem);
  if (!(result.rms_px <= acceptance.max_rms_px))
    v.reasons.push_back("the stereo RMS " + fixed(result.rms_px, 3) + " px exceeds " +
                        fixed(acceptance.max_rms_px, 1) +
                        " px: the lens model does not fit the corners (views not simultaneous, a bent board, "
                        "a wrong flip)");
  const CalibrationCoverage& c = v.coverage;
  if (!(c.worst_f_sd_fraction <= acceptance.max_f_sd_fraction))
    v.reasons.push_back("the poses do not pin the focal length down: sd(f)/f " +
                        (std::isfinite(c.worst_f_sd_fraction) ? fixed(100 * c.worst_f_sd_fraction, 3) + " %"
                                                             : std::string("undetermined")) +
                        ", at most " + fixed(100 * acceptance.max_f_sd_fraction, 2) + " % (" +
                        std::to_string(c.poses) + " frames, tilts spread over " + fixed(c.tilt_spread_deg, 1) +
                        " deg, corners over " + fixed(100 * c.view_fraction, 0) +
                        " % of the view): show the board at more tilts and places");
  return v;
}

}  // namespace onetip::vision
