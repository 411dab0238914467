#include "vision/stereo_calibration.hpp"

#include <cmath>
#include <opencv2/calib3d.hpp>

#include "core/error.hpp"

namespace onetip::vision {

namespace {
// fx, fy deviations from calibrateCamera's intrinsic deviations (fx fy cx cy
// k1 ...); a NaN (a singular fit) becomes +inf, "not determined".
cv::Vec2d focalDeviation(const cv::Mat& sd) {
  cv::Vec2d out{INFINITY, INFINITY};
  if (sd.total() < 2) return out;
  for (int i = 0; i < 2; ++i) {
    const double v = sd.at<double>(i);
    if (std::isfinite(v)) out[i] = v;
  }
  return out;
}
}  // namespace

void StereoCalibrationOptions::validate() const {
  if (min_pairs < 1) throw InputError("stereo calibration: min_pairs: must be at least 1");
}

StereoCalibrationResult calibrateStereo(const std::vector<BoardViewPair>& pairs,
                                        const MarkerPattern& pattern,
                                        const StereoCalibration& layout,
                                        const StereoCalibrationOptions& options) {
  options.validate();
  pattern.validate();
  if (static_cast<int>(pairs.size()) < options.min_pairs)
    throw InputError("stereo calibration: the board was found in both views of " +
                     std::to_string(pairs.size()) + " frame(s); at least " +
                     std::to_string(options.min_pairs) + " are needed");
  std::vector<cv::Point3f> board;
  for (int r = 0; r < pattern.rows; ++r)
    for (int c = 0; c < pattern.cols; ++c)
      board.emplace_back(static_cast<float>(c * pattern.square_mm),
                         static_cast<float>(r * pattern.square_mm), 0.0f);
  std::vector<std::vector<cv::Point3f>> object;
  std::vector<std::vector<cv::Point2f>> left, right;
  for (const auto& p : pairs) {
    if (static_cast<int>(p.left.size()) != pattern.count() ||
        static_cast<int>(p.right.size()) != pattern.count())
      throw InputError("stereo calibration: a board view has the wrong number of corners");
    object.push_back(board);
    left.push_back(p.left);
    right.push_back(p.right);
  }
  const cv::Size left_size(layout.split_x, layout.image_height);
  const cv::Size right_size(layout.image_width - layout.split_x, layout.image_height);

  StereoCalibrationResult result;
  result.pairs_used = static_cast<int>(pairs.size());
  cv::Mat K1, D1, K2, D2, R, T, E, F;
  try {
    std::vector<cv::Mat> rvecs, tvecs, unused_r, unused_t;
    cv::Mat sd_left, sd_right, sd_extrinsic, per_view;
    result.rms_left_px = cv::calibrateCamera(object, left, left_size, K1, D1, rvecs, tvecs, sd_left,
                                             sd_extrinsic, per_view);
    result.rms_right_px = cv::calibrateCamera(object, right, right_size, K2, D2, unused_r, unused_t,
                                              sd_right, sd_extrinsic, per_view);
    result.sd_f_left = focalDeviation(sd_left);
    result.sd_f_right = focalDeviation(sd_right);
    for (size_t i = 0; i < rvecs.size(); ++i) {
      const cv::Mat r = rvecs[i].reshape(1, 3), t = tvecs[i].reshape(1, 3);
      result.board_rvecs.emplace_back(r.at<double>(0), r.at<double>(1), r.at<double>(2));
      result.board_tvecs.emplace_back(t.at<double>(0), t.at<double>(1), t.at<double>(2));
    }
    const int flags = options.refine_jointly ? cv::CALIB_USE_INTRINSIC_GUESS : cv::CALIB_FIX_INTRINSIC;
    // Right view size: the same for both in stereoCalibrate's API, which only
    // uses it for initialisation that USE_INTRINSIC_GUESS / FIX_INTRINSIC skip.
    result.rms_px = cv::stereoCalibrate(
        object, left, right, K1, D1, K2, D2, left_size, R, T, E, F, flags,
        cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-7));
  } catch (const cv::Exception& e) {
    throw InputError(std::string("stereo calibration: the fit failed: ") + e.err);
  }
  if (!std::isfinite(result.rms_px))
    throw InputError("stereo calibration: the fit diverged (non-finite error)");
  StereoCalibration& c = result.calibration;
  c = layout;
  c.K_left = cv::Matx33d(K1);
  c.K_right = cv::Matx33d(K2);
  for (int i = 0; i < 5; ++i) {
    c.D_left[i] = D1.at<double>(i);
    c.D_right[i] = D2.at<double>(i);
  }
  c.R = cv::Matx33d(R);
  c.T = cv::Vec3d(T.at<double>(0), T.at<double>(1), T.at<double>(2));
  c.validate();
  return result;
}

}  // namespace onetip::vision
