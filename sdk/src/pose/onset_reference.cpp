#include "pose/onset_reference.hpp"

#include <algorithm>
#include <cmath>

namespace onetip::pose {

Eigen::Vector3d onsetReferencePoint(const contact::ContactField& field, const MarkerField& now,
                                    const std::vector<int>& region_markers, const Eigen::Vector3d& fallback) {
  const size_t n = field.displacement.size();
  const auto measured = [&](size_t i) { return i < now.valid.size() && now.valid[i] && field.valid[i]; };
  double max_normal = 0;
  for (size_t i = 0; i < n; ++i)
    if (measured(i)) max_normal = std::max(max_normal, std::abs(field.displacement[i].z()));
  std::vector<std::uint8_t> passes(n, 0);
  for (size_t i = 0; i < n; ++i)
    passes[i] = measured(i) && field.displacement[i].norm() >= kPaperRegionFraction * max_normal;

  std::vector<std::uint8_t> taken(n, 0);
  const bool lattice = now.rows > 0 && now.cols > 0 && static_cast<size_t>(now.rows) * now.cols == n;
  if (!lattice) {
    taken = passes;
  } else {  // grow from the tracked region over 8-connected markers that pass the cut
    std::vector<int> open;
    for (int id : region_markers) {
      const size_t i = static_cast<size_t>(id);
      if (passes[i] && !taken[i]) taken[i] = 1, open.push_back(id);
    }
    while (!open.empty()) {
      const int id = open.back();
      open.pop_back();
      const int r = id / now.cols, c = id % now.cols;
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          const int rr = r + dr, cc = c + dc;
          if (rr < 0 || cc < 0 || rr >= now.rows || cc >= now.cols) continue;
          const size_t j = static_cast<size_t>(rr * now.cols + cc);
          if (passes[j] && !taken[j]) taken[j] = 1, open.push_back(static_cast<int>(j));
        }
    }
  }
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int count = 0;
  for (size_t i = 0; i < n; ++i)
    if (taken[i]) sum += now.position[i] - field.displacement[i], ++count;
  return count > 0 ? Eigen::Vector3d(sum / count) : fallback;
}

}  // namespace onetip::pose
