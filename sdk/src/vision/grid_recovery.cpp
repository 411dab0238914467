#include "vision/grid_recovery.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <utility>

#include "vision/grid_graph.hpp"

namespace onetip::vision {

int recoverThroughLinks(const std::vector<Corner>& corners, const ViewHalf& view, const MarkerPattern& pattern,
                        const std::vector<cv::Point2f>& predicted, const std::vector<float>& max_distance,
                        ViewMarkers& markers) {
  if (corners.size() < 4) return 0;
  const GridLabelling g = labelGrid(corners, view, pattern.rows, pattern.cols);
  // The tracked marker on each corner, if any.
  std::vector<int> tracked(corners.size(), -1);
  for (int id = 0; id < pattern.count(); ++id) {
    if (!markers.valid[static_cast<size_t>(id)]) continue;
    for (size_t i = 0; i < corners.size(); ++i) {
      const cv::Point2f d = corners[i].pt - markers.point[static_cast<size_t>(id)];
      if (d.dot(d) < 0.25f) tracked[i] = id;
    }
  }
  std::map<std::pair<int, int>, int> votes;
  int total = 0;
  for (size_t i = 0; i < corners.size(); ++i) {
    if (tracked[i] < 0 || g.row[i] < 0) continue;
    ++votes[{pattern.rowOf(tracked[i]) - g.row[i], pattern.colOf(tracked[i]) - g.col[i]}];
    ++total;
  }
  std::pair<int, int> offset{0, 0};
  int best = 0;
  for (const auto& [key, n] : votes)
    if (n > best) best = n, offset = key;
  if (best < 3 || 5 * best < 4 * total) return 0;
  int added = 0;
  for (size_t i = 0; i < corners.size(); ++i) {
    if (tracked[i] >= 0 || g.row[i] < 0) continue;
    const int r = g.row[i] + offset.first, c = g.col[i] + offset.second;
    if (r < 0 || c < 0 || r >= pattern.rows || c >= pattern.cols) continue;
    const int id = pattern.id(r, c);
    const size_t k = static_cast<size_t>(id);
    if (markers.valid[k]) continue;
    const cv::Point2f d = corners[i].pt - predicted[k];
    if (d.dot(d) > max_distance[k] * max_distance[k]) continue;
    markers.set(id, corners[i].pt);
    ++added;
  }
  return added;
}

int relabelAnchored(const std::vector<Corner>& corners, const ViewHalf& view, const MarkerPattern& pattern,
                    const std::vector<cv::Point2f>& last, float max_median_px, ViewMarkers& markers) {
  if (corners.size() < 4) return 0;
  const GridLabelling g = labelGrid(corners, view, pattern.rows, pattern.cols);
  if (g.labelled < 4 || g.rows > pattern.rows || g.cols > pattern.cols) return 0;
  float best = std::numeric_limits<float>::max();
  std::pair<int, int> offset{0, 0};
  std::vector<float> d;
  for (int dr = 0; dr <= pattern.rows - g.rows; ++dr) {
    for (int dc = 0; dc <= pattern.cols - g.cols; ++dc) {
      d.clear();
      for (size_t i = 0; i < corners.size(); ++i)
        if (g.row[i] >= 0) d.push_back(static_cast<float>(cv::norm(corners[i].pt - last[static_cast<size_t>(pattern.id(g.row[i] + dr, g.col[i] + dc))])));
      std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
      if (d[d.size() / 2] < best) best = d[d.size() / 2], offset = {dr, dc};
    }
  }
  if (best > max_median_px) return 0;
  for (size_t i = 0; i < corners.size(); ++i)
    if (g.row[i] >= 0) markers.set(pattern.id(g.row[i] + offset.first, g.col[i] + offset.second), corners[i].pt);
  return markers.count();
}

int relabelByMajority(const std::vector<Corner>& corners, const ViewHalf& view, const MarkerPattern& pattern,
                      ViewMarkers& markers) {
  if (corners.size() < 4) return 0;
  const GridLabelling g = labelGrid(corners, view, pattern.rows, pattern.cols);
  std::vector<int> on(corners.size(), -1);  // the marker on each labelled corner
  std::map<std::pair<int, int>, int> votes;
  int total = 0;
  for (int id = 0; id < pattern.count(); ++id) {
    if (!markers.valid[static_cast<size_t>(id)]) continue;
    for (size_t i = 0; i < corners.size(); ++i) {
      const cv::Point2f d = corners[i].pt - markers.point[static_cast<size_t>(id)];
      if (g.row[i] < 0 || d.dot(d) >= 0.25f) continue;
      on[i] = id;
      ++votes[{pattern.rowOf(id) - g.row[i], pattern.colOf(id) - g.col[i]}];
      ++total;
    }
  }
  std::pair<int, int> offset{0, 0};
  int best = 0;
  for (const auto& [key, n] : votes)
    if (n > best) best = n, offset = key;
  if (best < 3 || 2 * best < total) return 0;
  int changed = 0;
  ViewMarkers out = markers;
  for (size_t i = 0; i < corners.size(); ++i) {
    if (g.row[i] < 0) continue;
    const int r = g.row[i] + offset.first, c = g.col[i] + offset.second;
    if (on[i] >= 0 && (r < 0 || c < 0 || r >= pattern.rows || c >= pattern.cols || pattern.id(r, c) != on[i]))
      out.clear(on[i]), ++changed;  // a marker on a corner the labelling gives another id (or none)
  }
  for (size_t i = 0; i < corners.size(); ++i) {
    if (g.row[i] < 0) continue;
    const int r = g.row[i] + offset.first, c = g.col[i] + offset.second;
    if (r < 0 || c < 0 || r >= pattern.rows || c >= pattern.cols) continue;
    const size_t k = static_cast<size_t>(pattern.id(r, c));
    if (out.valid[k] && out.point[k] == corners[i].pt) continue;
    if (!markers.valid[k] || markers.point[k] != corners[i].pt) ++changed;
    out.set(pattern.id(r, c), corners[i].pt);
  }
  markers = std::move(out);
  return changed;
}

}  // namespace onetip::vision
