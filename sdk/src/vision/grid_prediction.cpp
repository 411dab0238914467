#include "vision/grid_prediction.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace onetip::vision {
namespace {

template <size_t N>
float median(std::array<float, N>& v, size_t n) {
  std::nth_element(v.begin(), v.begin() + static_cast<long>(n / 2), v.begin() + static_cast<long>(n));
  float m = v[n / 2];
  if (n % 2 == 0) m = 0.5f * (m + *std::max_element(v.begin(), v.begin() + static_cast<long>(n / 2)));
  return m;
}

}  // namespace

std::optional<cv::Point2f> predictFromNeighbours(const LatticeView& g, int r, int c) {
  std::array<float, 10> xs{}, ys{};
  size_t n = 0;
  const auto add = [&](cv::Point2f p) { xs[n] = p.x, ys[n] = p.y, ++n; };
  if (g.has(r, c - 1) && g.has(r, c + 1)) add(0.5f * (g.at(r, c - 1) + g.at(r, c + 1)));
  if (g.has(r - 1, c) && g.has(r + 1, c)) add(0.5f * (g.at(r - 1, c) + g.at(r + 1, c)));
  constexpr int kDir[4][2] = {{0, 1}, {0, -1}, {1, 0}, {-1, 0}};
  for (const auto& d : kDir) {
    if (g.has(r + d[0], c + d[1]) && g.has(r + 2 * d[0], c + 2 * d[1]))
      add(2.0f * g.at(r + d[0], c + d[1]) - g.at(r + 2 * d[0], c + 2 * d[1]));
  }
  for (int dr = -1; dr <= 1; dr += 2) {
    for (int dc = -1; dc <= 1; dc += 2) {
      if (g.has(r + dr, c) && g.has(r, c + dc) && g.has(r + dr, c + dc))
        add(g.at(r + dr, c) + g.at(r, c + dc) - g.at(r + dr, c + dc));
    }
  }
  if (n == 0) return std::nullopt;
  return cv::Point2f(median(xs, n), median(ys, n));
}

std::optional<float> closeCompletion(const LatticeView& g, int r, int c, cv::Point2f p) {
  float worst = 0;
  int midpoints = 0, count = 0;
  const auto add = [&](cv::Point2f q) { worst = std::max(worst, static_cast<float>(cv::norm(q - p))), ++count; };
  if (g.has(r, c - 1) && g.has(r, c + 1)) add(0.5f * (g.at(r, c - 1) + g.at(r, c + 1))), ++midpoints;
  if (g.has(r - 1, c) && g.has(r + 1, c)) add(0.5f * (g.at(r - 1, c) + g.at(r + 1, c))), ++midpoints;
  for (int dr = -1; dr <= 1; dr += 2)
    for (int dc = -1; dc <= 1; dc += 2)
      if (g.has(r + dr, c) && g.has(r, c + dc) && g.has(r + dr, c + dc)) add(g.at(r + dr, c) + g.at(r, c + dc) - g.at(r + dr, c + dc));
  if (midpoints == 0 || count < 3) return std::nullopt;
  return worst;
}

namespace {
size_t linkLengths(const LatticeView& g, int r, int c, cv::Point2f p, std::array<float, 4>& d) {
  size_t n = 0;
  constexpr int kDir[4][2] = {{0, 1}, {0, -1}, {1, 0}, {-1, 0}};
  for (const auto& k : kDir) {
    if (!g.has(r + k[0], c + k[1])) continue;
    const cv::Point2f v = g.at(r + k[0], c + k[1]) - p;
    d[n++] = std::sqrt(v.dot(v));
  }
  return n;
}
}  // namespace

float localSpacing(const LatticeView& g, int r, int c, cv::Point2f p) {
  std::array<float, 4> d{};
  const size_t n = linkLengths(g, r, c, p, d);
  return n == 0 ? 0.0f : median(d, n);
}

float shortestLink(const LatticeView& g, int r, int c, cv::Point2f p) {
  std::array<float, 4> d{};
  const size_t n = linkLengths(g, r, c, p, d);
  return n == 0 ? 0.0f : *std::min_element(d.begin(), d.begin() + static_cast<long>(n));
}

}  // namespace onetip::vision
