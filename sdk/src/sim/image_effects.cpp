#include "sim/image_effects.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "core/option_checks.hpp"

namespace onetip::sim {

namespace {

// Independent random stream per effect, so switching one effect on or off
// leaves the others' realisations unchanged (splitmix64 finaliser).
cv::RNG streamFor(std::uint64_t seed, std::uint64_t effect) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (effect + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return cv::RNG(z ^ (z >> 31));
}

enum Stream : std::uint64_t { kBand, kDust, kSpecular, kLighting, kNoise };

const std::vector<float>& standardNormalTable() {
  static const std::vector<float> table = [] {
    cv::Mat1d samples(1, 1 << 16);
    cv::RNG(0x5EED).fill(samples, cv::RNG::NORMAL, 0.0, 1.0);
    cv::Scalar mean, stddev;
    cv::meanStdDev(samples, mean, stddev);
    std::vector<float> t(samples.total());
    for (size_t i = 0; i < t.size(); ++i) t[i] = static_cast<float>((samples(0, int(i)) - mean[0]) / stddev[0]);
    return t;
  }();
  return table;
}

// The band enters from one side and stops where it has covered `fraction` of the pad pixels.
void occludingBand(cv::Mat1f& grey, const cv::Mat1b& pad, double fraction, cv::RNG rng) {
  const int side = rng.uniform(0, 4);  // 0 left, 1 right, 2 top, 3 bottom
  const bool along_columns = side < 2;
  cv::Mat1i counts;
  cv::reduce(pad / 255, counts, along_columns ? 0 : 1, cv::REDUCE_SUM, CV_32S);
  const int n = static_cast<int>(counts.total());
  const double total = cv::sum(counts)[0];
  const bool from_start = side == 0 || side == 2;
  int covered_lines = 0;
  if (total > 0) {
    double cumulative = 0;
    while (covered_lines < n) {
      const int line = from_start ? covered_lines : n - 1 - covered_lines;
      const double next = cumulative + counts(line);
      if (std::abs(next - fraction * total) > std::abs(cumulative - fraction * total)) break;
      cumulative = next;
      ++covered_lines;
    }
  } else {
    covered_lines = static_cast<int>(std::lround(fraction * n));
  }
  const int start = from_start ? 0 : n - covered_lines;
  const cv::Rect band = along_columns ? cv::Rect(start, 0, covered_lines, grey.rows)
                                      : cv::Rect(0, start, grey.cols, covered_lines);
  grey(band).setTo(kOccluderGrey);
}

cv::Point2d pointIn(const cv::Rect& r, cv::RNG& rng) {
  return {rng.uniform(double(r.x), double(r.x + r.width)), rng.uniform(double(r.y), double(r.y + r.height))};
}

void dustBlobs(cv::Mat1f& grey, const cv::Rect& where, int count, cv::RNG rng) {
  for (int i = 0; i < count; ++i) {
    const cv::Point2d c = pointIn(where, rng);
    const double radius = rng.uniform(3.0, 12.0), darkness = rng.uniform(0.6, 0.9);
    forDisc(grey, c, radius, [&](float& g, double d) {
      const double t = std::clamp((radius - d) / (0.4 * radius), 0.0, 1.0);  // 1 in the core, soft rim
      g *= static_cast<float>(1.0 - darkness * t * t * (3 - 2 * t));
    });
  }
}

void specularSpots(cv::Mat1f& grey, const cv::Rect& where, int count, cv::RNG rng) {
  constexpr double kPeak = 400.0;
  for (int i = 0; i < count; ++i) {
    const cv::Point2d c = pointIn(where, rng);
    const double sigma = rng.uniform(1.0, 4.0);
    forDisc(grey, c, 3 * sigma,
            [&](float& g, double d) { g += static_cast<float>(kPeak * std::exp(-0.5 * d * d / (sigma * sigma))); });
  }
}

void lighting(cv::Mat1f& grey, const ImageEffects& e, cv::RNG rng) {
  const double angle = rng.uniform(0.0, 2 * std::numbers::pi);
  const double dx = std::cos(angle), dy = std::sin(angle);
  const double cx = 0.5 * (grey.cols - 1), cy = 0.5 * (grey.rows - 1);
  const double extent = std::abs(dx) * grey.cols + std::abs(dy) * grey.rows;
  const double inv_corner2 = 1.0 / (cx * cx + cy * cy);
  for (int y = 0; y < grey.rows; ++y) {
    float* row = grey.ptr<float>(y);
    for (int x = 0; x < grey.cols; ++x) {
      const double ramp = 1 + e.light_gradient * ((x - cx) * dx + (y - cy) * dy) / extent;
      const double vignette = 1 - e.vignetting * ((x - cx) * (x - cx) + (y - cy) * (y - cy)) * inv_corner2;
      row[x] *= static_cast<float>(e.exposure * ramp * vignette);
    }
  }
}

}  // namespace

void ImageEffects::validate() const {
  requireInRange("image effects: noise_sigma", noise_sigma, 0, 50, "grey levels");
  requireInRange("image effects: blur_sigma", blur_sigma, 0, 20, "px");
  requireInRange("image effects: vignetting", vignetting, 0, 1);
  requireInRange("image effects: exposure", exposure, 0.2, 3);
  requireInRange("image effects: light_gradient", light_gradient, 0, 1);
  requireInRange("image effects: dust_blobs", dust_blobs, 0, 200, "per view");
  requireInRange("image effects: specular_spots", specular_spots, 0, 200, "per view");
  requireInRange("image effects: occlusion_fraction", occlusion_fraction, 0, 0.9);
}

void applyImageEffects(cv::Mat1f& grey, const cv::Mat1b& pad, const ImageEffects& e, std::uint64_t seed) {
  if (e.occlusion_fraction > 0) occludingBand(grey, pad, e.occlusion_fraction, streamFor(seed, kBand));
  if (e.dust_blobs > 0 || e.specular_spots > 0) {
    cv::Rect on_pad = cv::boundingRect(pad);
    if (on_pad.empty()) on_pad = cv::Rect(0, 0, grey.cols, grey.rows);
    dustBlobs(grey, on_pad, e.dust_blobs, streamFor(seed, kDust));
    specularSpots(grey, on_pad, e.specular_spots, streamFor(seed, kSpecular));
  }
  if (e.exposure != 1 || e.light_gradient > 0 || e.vignetting > 0) lighting(grey, e, streamFor(seed, kLighting));
  if (e.blur_sigma > 0) cv::GaussianBlur(grey, grey, cv::Size(), e.blur_sigma, e.blur_sigma,
                     cv::BORDER_REPLICATE | cv::BORDER_ISOLATED);  // grey may be one half of a frame
}

void developView(cv::Mat1f& grey, const std::function<cv::Mat1b()>& pad_mask, const ImageEffects& e,
                 std::uint64_t frame_seed, int view_index, bool mirror, cv::Mat out) {
  const std::uint64_t seed = 2 * frame_seed + static_cast<std::uint64_t>(view_index);
  const std::uint64_t layout = 2 * e.layout_seed + static_cast<std::uint64_t>(view_index);
  const bool needs_pad = e.occlusion_fraction > 0 || e.dust_blobs > 0 || e.specular_spots > 0;
  applyImageEffects(grey, needs_pad ? pad_mask() : cv::Mat1b(), e, layout);
  exposeToSensor(grey, e.noise_sigma, seed, mirror, out);
}

void exposeToSensor(const cv::Mat1f& grey, double noise_sigma, std::uint64_t seed, bool mirror, cv::Mat out) {
  CV_Assert(out.type() == CV_8UC1 && out.size() == grey.size());
  const std::vector<float>& normal = standardNormalTable();
  std::uint64_t state = static_cast<std::uint64_t>(streamFor(seed, kNoise).state) | 1;  // xorshift needs != 0
  std::uint64_t bits = 0;  // four 16-bit table indices per xorshift step
  int indices_left = 0;
  const auto sigma = static_cast<float>(noise_sigma);
  const int last = grey.cols - 1;
  for (int y = 0; y < grey.rows; ++y) {
    const float* in = grey.ptr<float>(y);
    uchar* row = out.ptr<uchar>(y);
    for (int x = 0; x < grey.cols; ++x) {
      float value = in[x];
      if (sigma > 0) {
        if (indices_left == 0) {
          state ^= state << 13, state ^= state >> 7, state ^= state << 17;
          bits = state, indices_left = 4;
        }
        value += sigma * normal[bits & 0xFFFF];
        bits >>= 16, --indices_left;
      }
      row[mirror ? last - x : x] = cv::saturate_cast<uchar>(value);
    }
  }
}

}  // namespace onetip::sim
