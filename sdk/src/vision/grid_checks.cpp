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

namespace {

// The polygon of N lattice vertices `at` (cyclic) around a marker or a pair
// of markers, open where a vertex lies beyond the pattern, with the point
// its vertices put the middle at: the mean of the midpoints of the opposite
// vertices (k, k + N/2) that are there. margin(p): per edge, p's signed
// distance over the middle's; the smallest (see cellMargin in the header).
template <int N>
struct OpenPolygon {
  cv::Point2f v[N];
  bool have[N] = {};
  int count = 0;
  float inner[N] = {};  // per edge k -> k+1 present: the middle's side, times |edge|

  // Nothing when a vertex inside the pattern is missing from `grid`, no
  // opposite pair is there, or the polygon is degenerate or not convex.
  static std::optional<OpenPolygon> gather(const LatticeView& grid, const int (&at)[N][2]) {
    OpenPolygon poly;
    for (int k = 0; k < N; ++k) {
      const int r = at[k][0], c = at[k][1];
      if (grid.has(r, c)) poly.v[k] = grid.at(r, c), poly.have[k] = true, ++poly.count;
      else if (r >= 0 && c >= 0 && r < grid.rows && c < grid.cols) return std::nullopt;  // it may lie anywhere
    }
    cv::Point2f middle(0, 0);
    int pairs = 0;
    for (int k = 0; k < N / 2; ++k)
      if (poly.have[k] && poly.have[k + N / 2]) middle += 0.5f * (poly.v[k] + poly.v[k + N / 2]), ++pairs;
    if (pairs == 0) return std::nullopt;
    middle *= 1.0f / static_cast<float>(pairs);
    float turn = 0.0f;
    for (int k = 0; k < N; ++k) {
      const int j = (k + 1) % N, l = (k + 2) % N;
      if (!poly.have[k] || !poly.have[j]) continue;
      const cv::Point2f edge = poly.v[j] - poly.v[k];
      poly.inner[k] = static_cast<float>(edge.cross(middle - poly.v[k]));
      if (poly.inner[k] == 0.0f) return std::nullopt;
      if (poly.have[l]) {
        const auto bend = static_cast<float>(edge.cross(poly.v[l] - poly.v[j]));
        if (bend == 0.0f || bend * turn < 0.0f || bend * poly.inner[k] <= 0.0f) return std::nullopt;  // not convex
        turn = bend;
      }
    }
    return poly;
  }

  float margin(cv::Point2f p) const {
    float m = 1.0f;
    for (int k = 0; k < N; ++k) {
      const int j = (k + 1) % N;
      if (have[k] && have[j]) m = std::min(m, static_cast<float>((v[j] - v[k]).cross(p - v[k])) / inner[k]);
    }
    return m;
  }
};

}  // namespace

std::optional<float> cellMargin(const LatticeView& grid, int r, int c, cv::Point2f p) {
  // Cyclic: right, down, left, up.
  const int at[4][2] = {{r, c + 1}, {r + 1, c}, {r, c - 1}, {r - 1, c}};
  const auto cell = OpenPolygon<4>::gather(grid, at);
  if (!cell || cell->count < 3) return std::nullopt;
  return cell->margin(p);
}

std::optional<std::pair<float, float>> pairCellMargins(const LatticeView& grid, int r, int c, int dr, int dc,
                                                       cv::Point2f pa, cv::Point2f pb) {
  // e: along the pair, n: across it; the hexagon in cyclic order.
  const int er = dr, ec = dc, nr = dc, nc = dr;
  const int at[6][2] = {{r + 2 * er, c + 2 * ec}, {r + er + nr, c + ec + nc}, {r + nr, c + nc},
                        {r - er, c - ec},         {r - nr, c - nc},           {r + er - nr, c + ec - nc}};
  const auto cell = OpenPolygon<6>::gather(grid, at);
  if (!cell) return std::nullopt;
  // The right way round: b beyond a along the pair's axis.
  cv::Point2f axis;
  if (cell->have[0] && cell->have[3]) axis = cell->v[0] - cell->v[3];
  else if (cell->have[1] && cell->have[2]) axis = cell->v[1] - cell->v[2];
  else if (cell->have[5] && cell->have[4]) axis = cell->v[5] - cell->v[4];
  else return std::nullopt;
  if ((pb - pa).dot(axis) <= 0.0f) return std::nullopt;
  return std::make_pair(cell->margin(pa), cell->margin(pb));
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
