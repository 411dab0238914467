// vision/subpixel_refiner.hpp — sub-pixel position of a checkerboard corner.
//
// Two methods, both iterated on a window resampled (bilinearly) around the
// current estimate q, until the distance left to the fixed point (estimated
// from the contraction of the last two steps) is below 0.005 px:
//  - GradientOrthogonality (as cv::cornerSubPix): every image gradient g_i at
//    pixel p_i near a corner is orthogonal to (q - p_i), so
//    q = (sum w_i g_i g_i^T)^-1 sum w_i g_i g_i^T p_i, Gaussian weights w_i;
//  - SaddleFit: least-squares quadratic I ~ a x^2 + b xy + c y^2 + d x + e y + f
//    over the Gaussian-weighted window; the corner is its saddle point
//    [2a b; b 2c] dq = -[d e]^T (a centred corner is an even function, so the
//    fit's linear terms vanish exactly there).
// Units: pixels, centres at integer coordinates.
#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <vector>

namespace onetip::vision {

enum class SubpixelMethod { GradientOrthogonality, SaddleFit };

struct SubpixelOptions {
  SubpixelMethod method = SubpixelMethod::SaddleFit;
  int half_window = 5;        // window is (2 half_window + 1)^2 pixels
  float weight_sigma = 0.0f;  // Gaussian weight sigma in pixels; 0: half_window / 1.5
  int max_iterations = 8;
  float max_shift_px = 3.0f;  // giving up when the estimate wanders further from the start
  void validate() const;      // throws InputError naming the bad field
};

class SubpixelRefiner {
 public:
  explicit SubpixelRefiner(SubpixelOptions options = {});
  // The refined corner, or nothing when the window leaves the image, the
  // system is degenerate (no corner there) or the estimate wanders off.
  std::optional<cv::Point2f> refine(const cv::Mat& grey, cv::Point2f start) const;
  const SubpixelOptions& options() const noexcept { return options_; }

 private:
  static bool resample(const cv::Mat& grey, cv::Point2f q, int side, float* patch);
  std::optional<cv::Point2f> step(const cv::Mat& grey, cv::Point2f q) const;
  SubpixelOptions options_;
  std::vector<float> weight_;      // (2w+1)^2 Gaussian weights, row-major
  std::vector<float> saddle_fit_;  // 5 rows (a, b, c, d, e of the weighted fit) of saddle_stride_
  size_t saddle_stride_ = 0;       // (2w+1)^2 rounded up to a multiple of 8
};

}  // namespace onetip::vision
