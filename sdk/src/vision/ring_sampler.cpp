#include "vision/ring_sampler.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "vision/bilinear.hpp"

namespace onetip::vision {
namespace {

constexpr float kPi = 3.14159265358979f;
constexpr int kMaxSamples = 64;

struct RingStats {
  float mean = 0, contrast = 0, symmetry = 0;
  int changes = 0;
  std::array<float, kMaxSamples> value{};
  std::array<int, kMaxSamples> label{};
};

// Statistics of the ring values r.value[0..n).
void analyse(RingStats& r, int n) {
  float sum = 0;
  for (int k = 0; k < n; ++k) sum += r.value[k];
  r.mean = sum / static_cast<float>(n);
  float dev = 0, asym = 0;
  for (int k = 0; k < n; ++k) dev += std::abs(r.value[k] - r.mean);
  for (int k = 0; k < n / 2; ++k) asym += std::abs(r.value[k] - r.value[k + n / 2]);
  r.contrast = dev / static_cast<float>(n);
  if (r.contrast <= 0) return;
  r.symmetry = std::max(0.0f, 1.0f - asym / static_cast<float>(n / 2) / (2.0f * r.contrast));
  const float band = 0.25f * r.contrast;
  for (int k = 0; k < n; ++k) {
    const float d = r.value[k] - r.mean;
    r.label[k] = d > band ? 1 : (d < -band ? -1 : 0);
  }
  int last = 0;  // the last non-zero label, where the cyclic scan starts from
  for (int k = n - 1; k >= 0 && last == 0; --k) last = r.label[k];
  for (int k = 0; k < n; ++k) {  // cyclic label changes, skipping the band
    const int label = r.label[k];
    r.changes += (label != 0 && label != last) ? 1 : 0;
    last = label != 0 ? label : last;
  }
}

RingStats sampleRing(const cv::Mat& grey, cv::Point2f c, const std::vector<cv::Point2f>& offsets) {
  RingStats r;
  const int n = static_cast<int>(offsets.size());
  for (int k = 0; k < n; ++k) r.value[k] = sampleBilinear(grey, c.x + offsets[k].x, c.y + offsets[k].y);
  analyse(r, n);
  return r;
}

// Angle (radians, [0, 2pi)) where the ring's value crosses its mean between
// the non-zero-labelled samples a and b (b after a, cyclically).
float crossingAngle(const RingStats& r, int a, int b, int n) {
  const float step = 2.0f * kPi / static_cast<float>(n);
  for (int k = a; k != b; k = (k + 1) % n) {
    const int k1 = (k + 1) % n;
    const float d0 = r.value[k] - r.mean, d1 = r.value[k1] - r.mean;
    if ((d0 > 0) != (d1 > 0)) {
      const float t = d0 / (d0 - d1);
      return (static_cast<float>(k) + t) * step;
    }
  }
  return static_cast<float>(a) * step;
}

// The line through angles a and a' ~ a + pi, as an angle modulo pi.
float lineAngle(float a, float b) {
  const float x = std::cos(2 * a) + std::cos(2 * b), y = std::sin(2 * a) + std::sin(2 * b);
  float t = 0.5f * std::atan2(y, x);
  return t < 0 ? t + kPi : t;
}

float wrapPi(float a) {
  a = std::fmod(a, kPi);
  return a < 0 ? a + kPi : a;
}

}  // namespace

RingSampler::RingSampler(float inner_radius, float outer_radius, int samples)
    : outer_radius_(outer_radius), samples_(samples) {
  for (int k = 0; k < samples; ++k) {
    const float a = 2.0f * kPi * static_cast<float>(k) / static_cast<float>(samples);
    inner_offset_.emplace_back(inner_radius * std::cos(a), inner_radius * std::sin(a));
    outer_offset_.emplace_back(outer_radius * std::cos(a), outer_radius * std::sin(a));
    outer_pixel_.emplace_back(static_cast<int>(std::lround(outer_offset_.back().x)),
                              static_cast<int>(std::lround(outer_offset_.back().y)));
  }
}

bool RingSampler::quickFourSectors(const cv::Mat& grey, cv::Point centre, float min_contrast) const {
  RingStats r;
  for (int k = 0; k < samples_; ++k)
    r.value[k] = grey.at<unsigned char>(centre.y + outer_pixel_[k].y, centre.x + outer_pixel_[k].x);
  analyse(r, samples_);
  return r.changes == 4 && r.contrast >= min_contrast;
}

RingTest RingSampler::evaluate(const cv::Mat& grey, cv::Point2f centre) const {
  RingTest t;
  const RingStats in = sampleRing(grey, centre, inner_offset_);
  const RingStats out = sampleRing(grey, centre, outer_offset_);
  t.contrast = std::min(in.contrast, out.contrast);
  t.symmetry = std::min(in.symmetry, out.symmetry);
  t.four_sectors = in.changes == 4 && out.changes == 4;
  if (!t.four_sectors) return t;
  int both = 0, agree = 0;
  for (int k = 0; k < samples_; ++k) {
    if (in.label[k] == 0 || out.label[k] == 0) continue;
    ++both;
    agree += in.label[k] == out.label[k] ? 1 : 0;
  }
  t.phase_agreement = both > 0 ? static_cast<float>(agree) / static_cast<float>(both) : 0.0f;
  t.score = t.contrast * t.symmetry * t.phase_agreement;

  // The four crossings of the outer ring, in angular order.
  std::array<float, 4> cross{};
  std::array<int, 4> after{};  // label of the sector that follows each crossing
  int first = 0;
  while (out.label[first] == 0) ++first;
  int found = 0, prev = first;
  for (int step = 1; step <= samples_ && found < 4; ++step) {
    const int k = (first + step) % samples_;
    if (out.label[k] == 0) continue;
    if (out.label[k] != out.label[prev]) {
      cross[found] = crossingAngle(out, prev, k, samples_);
      after[found] = out.label[k];
      ++found;
    }
    prev = k;
  }
  t.edge_angle[0] = lineAngle(cross[0], cross[2]);
  t.edge_angle[1] = lineAngle(cross[1], cross[3]);
  // A dark sector: the one after crossing 0, or else the one after crossing 1.
  const int d = after[0] < 0 ? 0 : 1;
  float span = cross[d + 1] - cross[d];
  if (span < 0) span += 2 * kPi;
  t.dark_bisector = wrapPi(cross[d] + 0.5f * span);
  return t;
}

}  // namespace onetip::vision
