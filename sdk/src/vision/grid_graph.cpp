#include "vision/grid_graph.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <map>
#include <optional>
#include <utility>

#include "core/error.hpp"
#include "vision/bilinear.hpp"

namespace onetip::vision {
namespace {

constexpr float kPi = 3.14159265358979f;

cv::Point2f unit(float angle) { return {std::cos(angle), std::sin(angle)}; }

// Angle between two lines given modulo pi, in [0, pi/2].
float lineDifference(float a, float b) {
  float d = std::fmod(std::abs(a - b), kPi);
  return d > kPi / 2 ? kPi - d : d;
}

// Whether the segment a-b runs along an edge between a dark and a light
// square: at a quarter, half and three quarters of the way, the image a
// quarter of the length to either side differs by the contrast, same sign.
bool alongEdge(const ViewHalf& view, cv::Point2f a, cv::Point2f b, float contrast) {
  const cv::Point2f d = b - a, side = 0.25f * cv::Point2f(-d.y, d.x);
  const auto inside = [&](cv::Point2f r) { return r.x >= 0 && r.y >= 0 && r.x < view.width() - 1 && r.y < view.height() - 1; };
  int sign = 0;
  for (float t : {0.25f, 0.5f, 0.75f}) {
    const cv::Point2f p = view.toRaw(a + t * d + side), q = view.toRaw(a + t * d - side);
    if (!inside(p) || !inside(q)) return false;
    const float step = sampleBilinear(view.raw, p.x, p.y) - sampleBilinear(view.raw, q.x, q.y);
    if (std::abs(step) < contrast) return false;
    const int s = step > 0 ? 1 : -1;
    if (sign != 0 && s != sign) return false;
    sign = s;
  }
  return true;
}

// Mutual, opposite-colour links along the corners' edge directions.
std::vector<std::vector<int>> buildLinks(const std::vector<Corner>& corners, const ViewHalf& view, float cone_deg,
                                         float max_collinear_ratio) {
  const int n = static_cast<int>(corners.size());
  const float min_cos = std::cos(cone_deg * kPi / 180.0f);
  std::vector<std::array<int, 4>> best(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    for (int s = 0; s < 4; ++s) {
      const cv::Point2f u = unit(corners[i].edge_angle[s / 2] + (s % 2) * kPi);
      int arg = -1;
      float best_d2 = 0;
      for (int j = 0; j < n; ++j) {
        if (j == i) continue;
        const cv::Point2f d = corners[j].pt - corners[i].pt;
        const float d2 = d.dot(d);
        if (d2 <= 0 || (arg >= 0 && d2 >= best_d2)) continue;
        if (d.dot(u) < min_cos * std::sqrt(d2)) continue;
        arg = j, best_d2 = d2;
      }
      best[static_cast<size_t>(i)][static_cast<size_t>(s)] = arg;
    }
  }
  // Keep the mutual, opposite-colour links that run along an edge.
  std::vector<std::array<int, 4>> slot(static_cast<size_t>(n), std::array<int, 4>{-1, -1, -1, -1});
  for (int i = 0; i < n; ++i) {
    for (size_t s = 0; s < 4; ++s) {
      const int j = best[static_cast<size_t>(i)][s];
      if (j < 0) continue;
      const auto& back = best[static_cast<size_t>(j)];
      if (std::find(back.begin(), back.end(), i) == back.end()) continue;
      if (lineDifference(corners[i].dark_bisector, corners[j].dark_bisector) < kPi / 4) continue;  // same colour
      if (j > i && !alongEdge(view, corners[i].pt, corners[j].pt, std::min(corners[i].contrast, corners[j].contrast))) continue;
      if (j < i && std::find(slot[static_cast<size_t>(j)].begin(), slot[static_cast<size_t>(j)].end(), i) == slot[static_cast<size_t>(j)].end()) continue;
      slot[static_cast<size_t>(i)][s] = j;
    }
  }
  // Spacing: of two collinear links of a corner, a much longer one is a jump
  // over a gap (or across the border) and is dropped.
  const auto length = [&](int i, int j) { return static_cast<float>(cv::norm(corners[j].pt - corners[i].pt)); };
  std::vector<std::pair<int, int>> drop;
  for (int i = 0; i < n; ++i) {
    for (size_t s = 0; s < 4; s += 2) {
      const int a = slot[static_cast<size_t>(i)][s], b = slot[static_cast<size_t>(i)][s + 1];
      if (a < 0 || b < 0) continue;
      const float la = length(i, a), lb = length(i, b);
      if (la > max_collinear_ratio * lb) drop.emplace_back(i, a);
      if (lb > max_collinear_ratio * la) drop.emplace_back(i, b);
    }
  }
  std::vector<std::vector<int>> links(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    for (int j : slot[static_cast<size_t>(i)]) {
      if (j < 0) continue;
      const bool dropped = std::find(drop.begin(), drop.end(), std::make_pair(i, j)) != drop.end() ||
                           std::find(drop.begin(), drop.end(), std::make_pair(j, i)) != drop.end();
      if (!dropped) links[static_cast<size_t>(i)].push_back(j);
    }
  }
  return links;
}

struct Node {
  int row = 0, col = 0;
  cv::Point2f col_axis, row_axis;
  bool seen = false, conflict = false;
};

// Breadth-first labelling of the component of `seed`; returns its members.
std::vector<int> labelComponent(const std::vector<Corner>& corners, const std::vector<std::vector<int>>& links,
                                int seed, std::vector<Node>& nodes) {
  Node& s = nodes[static_cast<size_t>(seed)];
  s.seen = true;
  s.col_axis = unit(corners[seed].edge_angle[0]);
  s.row_axis = unit(corners[seed].edge_angle[1]);
  std::vector<int> members{seed};
  std::deque<int> queue{seed};
  while (!queue.empty()) {
    const int i = queue.front();
    queue.pop_front();
    const Node& a = nodes[static_cast<size_t>(i)];
    for (int j : links[static_cast<size_t>(i)]) {
      cv::Point2f v = corners[j].pt - corners[i].pt;
      v *= 1.0f / std::sqrt(v.dot(v));
      const float cc = v.dot(a.col_axis), cr = v.dot(a.row_axis);
      if (std::max(std::abs(cc), std::abs(cr)) < 0.8f) continue;
      Node b;
      b.row = a.row + (std::abs(cc) >= std::abs(cr) ? 0 : (cr > 0 ? 1 : -1));
      b.col = a.col + (std::abs(cc) >= std::abs(cr) ? (cc > 0 ? 1 : -1) : 0);
      const cv::Point2f e0 = unit(corners[j].edge_angle[0]), e1 = unit(corners[j].edge_angle[1]);
      const bool first_is_col = std::abs(e0.dot(a.col_axis)) >= std::abs(e1.dot(a.col_axis));
      b.col_axis = first_is_col ? e0 : e1;
      b.row_axis = first_is_col ? e1 : e0;
      if (b.col_axis.dot(a.col_axis) < 0) b.col_axis = -b.col_axis;
      if (b.row_axis.dot(a.row_axis) < 0) b.row_axis = -b.row_axis;
      Node& target = nodes[static_cast<size_t>(j)];
      if (target.seen) {
        if (target.row != b.row || target.col != b.col) target.conflict = true;
        continue;
      }
      b.seen = true;
      target = b;
      members.push_back(j);
      queue.push_back(j);
    }
  }
  // Drop conflicting corners and labels claimed twice.
  std::map<std::pair<int, int>, int> claims;
  for (int m : members) ++claims[{nodes[static_cast<size_t>(m)].row, nodes[static_cast<size_t>(m)].col}];
  std::vector<int> kept;
  for (int m : members) {
    const Node& nm = nodes[static_cast<size_t>(m)];
    if (!nm.conflict && claims[{nm.row, nm.col}] == 1) kept.push_back(m);
  }
  return kept;
}

// Removes sparse outer lines (a stray corner linked beyond the board) while
// the labelled extent exceeds rows x cols, the lattice's first axis mapped
// to `rows`. A line is only removed when it holds at most half the other
// axis's expected count. Returns the members kept, or nothing when the grid
// cannot be trimmed to that extent.
std::optional<std::vector<int>> trimToExtent(std::vector<int> members, const std::vector<Node>& nodes, int rows, int cols) {
  for (;;) {
    int lo[2] = {1 << 30, 1 << 30}, hi[2] = {-(1 << 30), -(1 << 30)};
    for (int m : members) {
      const int v[2] = {nodes[static_cast<size_t>(m)].row, nodes[static_cast<size_t>(m)].col};
      for (int a = 0; a < 2; ++a) lo[a] = std::min(lo[a], v[a]), hi[a] = std::max(hi[a], v[a]);
    }
    const int allowed[2] = {rows, cols};
    int axis = -1;
    for (int a = 0; a < 2; ++a)
      if (hi[a] - lo[a] + 1 > allowed[a]) axis = a;
    if (members.empty()) return std::nullopt;
    if (axis < 0) return members;
    int at_lo = 0, at_hi = 0;
    for (int m : members) {
      const int v = axis == 0 ? nodes[static_cast<size_t>(m)].row : nodes[static_cast<size_t>(m)].col;
      at_lo += v == lo[axis] ? 1 : 0, at_hi += v == hi[axis] ? 1 : 0;
    }
    const int line = at_lo <= at_hi ? lo[axis] : hi[axis];
    if (2 * std::min(at_lo, at_hi) > allowed[1 - axis]) return std::nullopt;  // a real line: a larger board
    std::erase_if(members, [&](int m) {
      return (axis == 0 ? nodes[static_cast<size_t>(m)].row : nodes[static_cast<size_t>(m)].col) == line;
    });
  }
}

}  // namespace

void GridGraphOptions::validate() const {
  if (!(link_cone_deg > 0.0f && link_cone_deg < 45.0f)) throw InputError("grid.link_cone_deg: must be in (0, 45)");
  if (!(max_collinear_ratio > 1.0f)) throw InputError("grid.max_collinear_ratio: must exceed 1");
}

GridLabelling labelGrid(const std::vector<Corner>& corners, const ViewHalf& view, int expected_rows,
                        int expected_cols, const GridGraphOptions& options) {
  options.validate();
  const int n = static_cast<int>(corners.size());
  GridLabelling out;
  out.row.assign(static_cast<size_t>(n), -1);
  out.col.assign(static_cast<size_t>(n), -1);
  const auto links = buildLinks(corners, view, options.link_cone_deg, options.max_collinear_ratio);

  // Seeds: the best-linked corners first; the largest component wins.
  std::vector<int> order(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) order[static_cast<size_t>(i)] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const size_t la = links[static_cast<size_t>(a)].size(), lb = links[static_cast<size_t>(b)].size();
    return la != lb ? la > lb : corners[a].score > corners[b].score;
  });
  std::vector<Node> nodes(static_cast<size_t>(n)), best_nodes;
  std::vector<int> best;
  for (int seed : order) {
    if (nodes[static_cast<size_t>(seed)].seen || links[static_cast<size_t>(seed)].empty()) continue;
    std::vector<Node> trial = nodes;
    std::vector<int> members = labelComponent(corners, links, seed, trial);
    for (size_t k = 0; k < trial.size(); ++k) nodes[k].seen = nodes[k].seen || trial[k].seen;
    if (members.size() > best.size()) best = std::move(members), best_nodes = std::move(trial);
    if (2 * best.size() > static_cast<size_t>(n)) break;  // no other component can be larger
  }
  if (best.size() < 2) return out;
  // Trim to the pattern in whichever of the two axis assignments keeps more.
  auto trimmed = trimToExtent(best, best_nodes, expected_rows, expected_cols);
  auto turned_trim = trimToExtent(best, best_nodes, expected_cols, expected_rows);
  if (turned_trim && (!trimmed || turned_trim->size() > trimmed->size())) trimmed = std::move(turned_trim);
  if (trimmed) best = std::move(*trimmed);

  // Mean lattice steps in the image, for the orientation.
  std::map<std::pair<int, int>, int> at;
  for (int m : best) at[{best_nodes[static_cast<size_t>(m)].row, best_nodes[static_cast<size_t>(m)].col}] = m;
  cv::Point2f col_step(0, 0), row_step(0, 0);
  for (int m : best) {
    const Node& a = best_nodes[static_cast<size_t>(m)];
    if (auto it = at.find({a.row, a.col + 1}); it != at.end()) col_step += corners[it->second].pt - corners[m].pt;
    if (auto it = at.find({a.row + 1, a.col}); it != at.end()) row_step += corners[it->second].pt - corners[m].pt;
  }
  bool swap_axes = std::abs(col_step.x) < std::abs(row_step.x);
  int min_r = 1 << 30, max_r = -(1 << 30), min_c = 1 << 30, max_c = -(1 << 30);
  for (int m : best) {
    min_r = std::min(min_r, best_nodes[static_cast<size_t>(m)].row), max_r = std::max(max_r, best_nodes[static_cast<size_t>(m)].row);
    min_c = std::min(min_c, best_nodes[static_cast<size_t>(m)].col), max_c = std::max(max_c, best_nodes[static_cast<size_t>(m)].col);
  }
  int extent_cols = (swap_axes ? max_r - min_r : max_c - min_c) + 1;
  int extent_rows = (swap_axes ? max_c - min_c : max_r - min_r) + 1;
  bool turned = false;  // the board is turned by about 90 deg: col along +y, row along -x
  if (expected_rows != expected_cols && extent_rows == expected_cols && extent_cols == expected_rows) {
    swap_axes = !swap_axes, turned = true;
    std::swap(extent_rows, extent_cols);
  }
  const cv::Point2f new_col = swap_axes ? row_step : col_step, new_row = swap_axes ? col_step : row_step;
  const bool flip_col = turned ? new_col.y < 0 : new_col.x < 0;
  const bool flip_row = turned ? new_row.x > 0 : new_row.y < 0;
  for (int m : best) {
    const Node& a = best_nodes[static_cast<size_t>(m)];
    int c = swap_axes ? a.row - min_r : a.col - min_c;
    int r = swap_axes ? a.col - min_c : a.row - min_r;
    if (flip_col) c = extent_cols - 1 - c;
    if (flip_row) r = extent_rows - 1 - r;
    out.row[static_cast<size_t>(m)] = r;
    out.col[static_cast<size_t>(m)] = c;
  }
  out.rows = extent_rows;
  out.cols = extent_cols;
  out.labelled = static_cast<int>(best.size());
  return out;
}

}  // namespace onetip::vision
