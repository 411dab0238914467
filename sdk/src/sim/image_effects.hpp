// sim/image_effects.hpp — the imaging defects added to one rendered view.
//
// Applied in this order to a view's float grey image (pinhole orientation,
// pixel centres at integers), deterministically from `seed`:
//   1. scene: an occluding band (grey kOccluderGrey) entering from one side
//      (chosen from the seed) and covering occlusion_fraction of the pad
//      pixels; dust blobs (dark soft discs, radius 3..12 px, 60..90 % dark)
//      and specular spots (Gaussian highlights, sigma 1..4 px, +400 grey
//      levels at the peak so their core saturates) placed on the pad's
//      bounding box;
//   2. lighting: grey *= exposure * (1 + light_gradient * t) * (1 - vignetting * r^2),
//      t in [-1/2, 1/2] the position along a seeded direction across the view,
//      r the distance from the view centre divided by the corner distance;
//   3. optics: Gaussian blur of blur_sigma px;
// then exposeToSensor() adds Gaussian noise of noise_sigma grey levels
// (drawn from a 2^16-entry table of standard normal samples, normalised to
// mean 0 and deviation 1, indexed by a seeded xorshift generator), rounds and
// saturates to 8 bits, mirroring the columns if asked.
// `pad` marks the pixels where the pad (some sheet) was drawn; it is only
// read by the occlusion, dust and specular effects.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <opencv2/core.hpp>

#include "sim/renderer.hpp"

namespace onetip::sim {

constexpr float kOccluderGrey = 8.0F;

// Calls paint(grey value, distance) for every pixel of `grey` within `radius` px of `centre`.
template <typename Paint>
void forDisc(cv::Mat1f& grey, cv::Point2d centre, double radius, Paint paint) {
  const int x0 = std::max(0, static_cast<int>(std::floor(centre.x - radius)));
  const int x1 = std::min(grey.cols - 1, static_cast<int>(std::ceil(centre.x + radius)));
  const int y0 = std::max(0, static_cast<int>(std::floor(centre.y - radius)));
  const int y1 = std::min(grey.rows - 1, static_cast<int>(std::ceil(centre.y + radius)));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const double d = std::hypot(x - centre.x, y - centre.y);
      if (d <= radius) paint(grey(y, x), d);
    }
}

void applyImageEffects(cv::Mat1f& grey, const cv::Mat1b& pad, const ImageEffects& effects, std::uint64_t seed);
// out: CV_8UC1 of grey's size (may be a view into a larger frame).
void exposeToSensor(const cv::Mat1f& grey, double noise_sigma, std::uint64_t seed, bool mirror, cv::Mat out);

// Both steps for view `view_index` (0 left, 1 right) of a frame: applyImageEffects
// (asking pad_mask() only if needed), seeded by effects.layout_seed and the
// view so static effects stay put, then exposeToSensor into `out`, whose noise
// is seeded by the frame's seed and the view.
void developView(cv::Mat1f& grey, const std::function<cv::Mat1b()>& pad_mask, const ImageEffects& effects,
                 std::uint64_t frame_seed, int view_index, bool mirror, cv::Mat out);

}  // namespace onetip::sim
