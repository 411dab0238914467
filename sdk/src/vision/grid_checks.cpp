#include "vision/grid_checks.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace onetip::vision {

LinkCheck checkLinks(const LatticeView& now, const LatticeView& before, int r, int c, float stretch) {
  LinkCheck out;
  if (!before.has(r, c)) return out;
  constexpr int kDir[4][2] = {{0, 1}, {1, 0}, {0, -1}, {-1, 0}};  // cyclic: right, down, left, up
  cv::Point2f link[4], old[4];
  bool have[4] = {false, false, false, false};
  for (int k = 0; k < 4; ++k) {
    const int nr = r + kDir[k][0], nc = c + kDir[k][1];
    if (!now.has(nr, nc) || !before.has(nr, nc)) continue;
    link[k] = now.at(nr, nc) - now.at(r, c), old[k] = before.at(nr, nc) - before.at(r, c);
    have[k] = true;
    const float ratio = std::sqrt(link[k].dot(link[k]) / std::max(old[k].dot(old[k]), 1e-6f));
    ++out.checked;
    if (link[k].dot(old[k]) <= 0 || ratio > stretch || ratio * stretch < 1.0f) ++out.bad;
  }
  for (int k = 0; k < 4; ++k) {
    const int j = (k + 1) % 4;
    if (have[k] && have[j] && link[k].cross(link[j]) * old[k].cross(old[j]) <= 0) ++out.crossed;
  }
  return out;
}

std::optional<float> cellMargin(const LatticeView& grid, int r, int c, cv::Point2f p) {
  constexpr int kDir[4][2] = {{0, 1}, {1, 0}, {0, -1}, {-1, 0}};  // cyclic: right, down, left, up
  cv::Point2f v[4];
  bool have[4] = {false, false, false, false};
  int count = 0;
  for (int k = 0; k < 4; ++k) {
    const int nr = r + kDir[k][0], nc = c + kDir[k][1];
    if (grid.has(nr, nc)) {
      v[k] = grid.at(nr, nc), have[k] = true, ++count;
    } else if (nr >= 0 && nc >= 0 && nr < grid.rows && nc < grid.cols) {
      return std::nullopt;  // a neighbour not measured: its corner may lie anywhere on that side
    }
  }
  if (count < 3) return std::nullopt;
  // (r, c) where its neighbours put it: the mean of the opposite pairs' midpoints.
  cv::Point2f centre(0, 0);
  int pairs = 0;
  for (int k = 0; k < 2; ++k)
    if (have[k] && have[k + 2]) centre += 0.5f * (v[k] + v[k + 2]), ++pairs;
  centre *= 1.0f / static_cast<float>(pairs);
  float margin = 1.0f, turn = 0.0f;
  for (int k = 0; k < 4; ++k) {
    const int j = (k + 1) % 4, l = (k + 2) % 4;
    if (!have[k] || !have[j]) continue;
    const cv::Point2f edge = v[j] - v[k];
    const auto inner = static_cast<float>(edge.cross(centre - v[k]));  // the centre's side, times |edge|
    if (have[l]) {
      const auto bend = static_cast<float>(edge.cross(v[l] - v[j]));
      if (bend == 0.0f || bend * turn < 0.0f || bend * inner <= 0.0f) return std::nullopt;  // not convex
      turn = bend;
    }
    if (inner == 0.0f) return std::nullopt;
    margin = std::min(margin, static_cast<float>(edge.cross(p - v[k])) / inner);
  }
  return margin;
}

std::optional<std::pair<float, float>> pairCellMargins(const LatticeView& grid, int r, int c, int dr, int dc,
                                                       cv::Point2f pa, cv::Point2f pb) {
  // e: along the pair, n: across it; the hexagon in cyclic order.
  const int er = dr, ec = dc, nr = dc, nc = dr;
  const int at[6][2] = {{r + 2 * er, c + 2 * ec}, {r + er + nr, c + ec + nc}, {r + nr, c + nc},
                        {r - er, c - ec},         {r - nr, c - nc},           {r + er - nr, c + ec - nc}};
  cv::Point2f v[6];
  bool have[6];
  for (int k = 0; k < 6; ++k) {
    const int vr = at[k][0], vc = at[k][1];
    have[k] = grid.has(vr, vc);
    if (have[k]) v[k] = grid.at(vr, vc);
    else if (vr >= 0 && vc >= 0 && vr < grid.rows && vc < grid.cols) return std::nullopt;
  }
  // Opposite pairs across the pair's centre: (0, 3), (1, 4), (2, 5).
  cv::Point2f centre(0, 0);
  int pairs = 0;
  for (int k = 0; k < 3; ++k)
    if (have[k] && have[k + 3]) centre += 0.5f * (v[k] + v[k + 3]), ++pairs;
  if (pairs == 0) return std::nullopt;
  centre *= 1.0f / static_cast<float>(pairs);
  // The right way round: b beyond a along the pair's axis.
  cv::Point2f axis;
  if (have[0] && have[3]) axis = v[0] - v[3];
  else if (have[1] && have[2]) axis = v[1] - v[2];
  else if (have[5] && have[4]) axis = v[5] - v[4];
  else return std::nullopt;
  if ((pb - pa).dot(axis) <= 0.0f) return std::nullopt;
  float ma = 1.0f, mb = 1.0f, turn = 0.0f;
  for (int k = 0; k < 6; ++k) {
    const int j = (k + 1) % 6, l = (k + 2) % 6;
    if (!have[k] || !have[j]) continue;
    const cv::Point2f edge = v[j] - v[k];
    const auto inner = static_cast<float>(edge.cross(centre - v[k]));
    if (inner == 0.0f) return std::nullopt;
    if (have[l]) {
      const auto bend = static_cast<float>(edge.cross(v[l] - v[j]));
      if (bend == 0.0f || bend * turn < 0.0f || bend * inner <= 0.0f) return std::nullopt;  // not convex
      turn = bend;
    }
    ma = std::min(ma, static_cast<float>(edge.cross(pa - v[k])) / inner);
    mb = std::min(mb, static_cast<float>(edge.cross(pb - v[k])) / inner);
  }
  return std::make_pair(ma, mb);
}

bool hasSeam(const ViewMarkers& m, float stretch, const CornerFinder& near) {
  const auto length2 = [&](int r, int c, int dr, int dc) {
    if (!m.has(r, c) || !m.has(r + dr, c + dc)) return -1.0f;
    const cv::Point2f d = m.at(r + dr, c + dc) - m.at(r, c);
    return d.dot(d);
  };
  for (int r = 0; r < m.rows; ++r) {
    for (int c = 0; c < m.cols; ++c) {
      for (const auto& [dr, dc] : {std::pair{0, 1}, std::pair{1, 0}}) {
        const float now = length2(r, c, dr, dc), before = length2(r - dr, c - dc, dr, dc),
                    after = length2(r + dr, c + dc, dr, dc);
        if (now < 0 || before < 0 || after < 0) continue;
        if (100.0f * now < std::min(before, after)) return true;
        if (now > stretch * stretch * std::max(before, after) &&
            near(0.5f * (m.at(r, c) + m.at(r + dr, c + dc)), 0.25f * std::sqrt(now)))
          return true;
      }
    }
  }
  return false;
}

}  // namespace onetip::vision
