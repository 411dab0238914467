#include "vision/grid_recovery.hpp"

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

}  // namespace onetip::vision
