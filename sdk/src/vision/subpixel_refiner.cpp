#include "vision/subpixel_refiner.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace onetip::vision {

void SubpixelOptions::validate() const {
  if (half_window < 2 || half_window > 15) throw InputError("subpixel.half_window: must be in 2..15");
  if (!(weight_sigma >= 0.0f) || weight_sigma > 50.0f) throw InputError("subpixel.weight_sigma: must be in 0..50");
  if (max_iterations < 1 || max_iterations > 100) throw InputError("subpixel.max_iterations: must be in 1..100");
  if (!(max_shift_px > 0.0f)) throw InputError("subpixel.max_shift_px: must be positive");
}

SubpixelRefiner::SubpixelRefiner(SubpixelOptions options) : options_(options) {
  options_.validate();
  const int w = options_.half_window, n = 2 * w + 1;
  const double sigma = options_.weight_sigma > 0 ? options_.weight_sigma : w / 1.5;
  weight_.resize(static_cast<size_t>(n * n));
  cv::Mat design(n * n, 6, CV_64F), weights(n * n, 1, CV_64F);
  for (int v = -w; v <= w; ++v) {
    for (int u = -w; u <= w; ++u) {
      const int i = (v + w) * n + (u + w);
      const double wt = std::exp(-(u * u + v * v) / (2 * sigma * sigma));
      weight_[static_cast<size_t>(i)] = static_cast<float>(wt);
      weights.at<double>(i) = wt;
      const double row[6] = {double(u * u), double(u * v), double(v * v), double(u), double(v), 1.0};
      for (int j = 0; j < 6; ++j) design.at<double>(i, j) = row[j];
    }
  }
  // Weighted least squares: theta = (A^T W A)^-1 A^T W I.
  cv::Mat weighted = design.clone();
  for (int i = 0; i < n * n; ++i) weighted.row(i) *= weights.at<double>(i);
  const cv::Mat fit = (design.t() * weighted).inv(cv::DECOMP_SVD) * weighted.t();  // 6 x n^2
  saddle_stride_ = static_cast<size_t>((n * n + 7) / 8 * 8);  // rows padded with zeros to whole lanes
  saddle_fit_.assign(5 * saddle_stride_, 0.0f);
  for (int r = 0; r < 5; ++r)
    for (int i = 0; i < n * n; ++i) saddle_fit_[static_cast<size_t>(r) * saddle_stride_ + static_cast<size_t>(i)] = static_cast<float>(fit.at<double>(r, i));
}

// One update of the estimate q: the window (plus a one-pixel ring for the
// gradients) resampled at q + integer offsets, then the method's solve.
// The window of side `side` centred on q, resampled bilinearly: patch[v * side + u]
// is the image at q + (u - side/2, v - side/2). False when it leaves the image.
bool SubpixelRefiner::resample(const cv::Mat& grey, cv::Point2f q, int side, float* patch) {
  const int half = side / 2;
  const float fx0 = std::floor(q.x), fy0 = std::floor(q.y);
  const int x0 = static_cast<int>(fx0) - half, y0 = static_cast<int>(fy0) - half;
  if (x0 < 0 || y0 < 0 || x0 + side >= grey.cols || y0 + side >= grey.rows) return false;
  // Separable: along x on side + 1 rows, then along y.
  const float ax = q.x - fx0, ay = q.y - fy0;
  float along_x[34 * 33];  // (side + 1) x side, side <= 33 by half_window <= 15
  for (int v = 0; v <= side; ++v) {
    const unsigned char* row = grey.ptr<unsigned char>(y0 + v) + x0;
    float* out = along_x + v * side;
    for (int u = 0; u < side; ++u) out[u] = static_cast<float>(row[u]) + ax * static_cast<float>(row[u + 1] - row[u]);
  }
  for (int v = 0; v < side; ++v) {
    const float* top = along_x + v * side;
    const float* bottom = top + side;
    float* out = patch + v * side;
    for (int u = 0; u < side; ++u) out[u] = top[u] + ay * (bottom[u] - top[u]);
  }
  return true;
}

// One update of the estimate q by the chosen method.
std::optional<cv::Point2f> SubpixelRefiner::step(const cv::Mat& grey, cv::Point2f q) const {
  const int w = options_.half_window, n = 2 * w + 1;
  float patch[33 * 33];  // (n + 2)^2 <= 33^2 by half_window <= 15
  double a = 0, b = 0, c = 0, d = 0, e = 0;
  if (options_.method == SubpixelMethod::GradientOrthogonality) {
    const int m = n + 2;  // one more pixel around, for the gradients
    if (!resample(grey, q, m, patch)) return std::nullopt;
    for (int v = -w; v <= w; ++v) {
      for (int u = -w; u <= w; ++u) {
        const int pi = (v + w + 1) * m + (u + w + 1);
        const float gx = 0.5f * (patch[pi + 1] - patch[pi - 1]);
        const float gy = 0.5f * (patch[pi + m] - patch[pi - m]);
        const float wt = weight_[static_cast<size_t>((v + w) * n + (u + w))];
        const double gxx = wt * gx * gx, gxy = wt * gx * gy, gyy = wt * gy * gy;
        a += gxx, b += gxy, c += gyy;
        d += gxx * u + gxy * v;
        e += gxy * u + gyy * v;
      }
    }
    const double det = a * c - b * b;
    if (det <= 1e-6 * (a + c) * (a + c)) return std::nullopt;  // an edge or a flat patch
    return cv::Point2f(q.x + static_cast<float>((c * d - b * e) / det), q.y + static_cast<float>((a * e - b * d) / det));
  }
  if (!resample(grey, q, n, patch)) return std::nullopt;
  std::fill(patch + n * n, patch + saddle_stride_, 0.0f);  // the padding lanes
  // Five dot products with the fit rows, eight independent lanes each (vectorised).
  const size_t stride = saddle_stride_;
  double coef[5];
  for (size_t r = 0; r < 5; ++r) {
    const float* f = saddle_fit_.data() + r * stride;
    float lane[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    for (size_t i = 0; i < stride; i += 8)
      for (size_t j = 0; j < 8; ++j) lane[j] += f[i + j] * patch[i + j];
    coef[r] = static_cast<double>(((lane[0] + lane[1]) + (lane[2] + lane[3])) + ((lane[4] + lane[5]) + (lane[6] + lane[7])));
  }
  a = 2 * coef[0], b = coef[1], c = 2 * coef[2], d = -coef[3], e = -coef[4];
  const double det = a * c - b * b;  // Hessian [a b; b c], solve H dq = -grad
  if (det >= 0) return std::nullopt;  // not a saddle
  float dx = static_cast<float>((c * d - b * e) / det), dy = static_cast<float>((a * e - b * d) / det);
  const float len = std::sqrt(dx * dx + dy * dy);
  if (len > 1.0f) dx /= len, dy /= len;  // the quadratic model is only local
  return cv::Point2f(q.x + dx, q.y + dy);
}

// Stops when the distance left to the fixed point is below 0.005 px. The
// iteration contracts linearly, so after moves m_{n-1}, m_n that distance is
// about |m_n| rho / (1 - rho), rho = |m_n| / |m_{n-1}| (the a-posteriori bound
// of a contraction); before a contraction is known, when |m_n| itself is.
std::optional<cv::Point2f> SubpixelRefiner::refine(const cv::Mat& grey, cv::Point2f start) const {
  constexpr float kTolerance = 0.005f;  // px
  cv::Point2f q = start;
  float last_move = 0.0f;
  for (int it = 0; it < options_.max_iterations; ++it) {
    const auto next = step(grey, q);
    if (!next) return std::nullopt;
    const cv::Point2f move = *next - q;
    q = *next;
    const cv::Point2f drift = q - start;
    if (drift.dot(drift) > options_.max_shift_px * options_.max_shift_px) return std::nullopt;
    const float length = std::sqrt(move.dot(move));
    if (length < kTolerance) break;
    if (it > 0 && length < last_move && length * length / (last_move - length) < kTolerance) break;
    last_move = length;
  }
  return q;
}

}  // namespace onetip::vision
