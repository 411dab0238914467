#include "pose/onset_reference.hpp"

#include "contact/grid_components.hpp"

namespace onetip::pose {

Eigen::Vector3d onsetReferencePoint(const contact::ContactField& field, const MarkerField& now,
                                    const std::vector<int>& region_markers, const Eigen::Vector3d& fallback) {
  const size_t n = field.displacement.size();
  const auto measured = [&](size_t i) { return i < now.valid.size() && now.valid[i] && field.valid[i]; };
  std::vector<std::uint8_t> taken(n, 0);
  for (size_t i = 0; i < n; ++i)
    taken[i] = measured(i) && field.displacement[i].norm() >= kPaperRegionFraction * field.max_normal_mm;
  if (now.rows > 0 && now.cols > 0 && static_cast<size_t>(now.rows) * static_cast<size_t>(now.cols) == n) {
    // Only the 8-connected components of that set that meet the tracked region.
    const std::vector<int> label = contact::labelGridComponents(now.rows, now.cols, taken, nullptr);
    std::vector<std::uint8_t> meets;
    for (int id : region_markers) {
      const int l = label[static_cast<size_t>(id)];
      if (l < 0) continue;
      if (static_cast<size_t>(l) >= meets.size()) meets.resize(static_cast<size_t>(l) + 1, 0);
      meets[static_cast<size_t>(l)] = 1;
    }
    for (size_t i = 0; i < n; ++i)
      taken[i] = label[i] >= 0 && static_cast<size_t>(label[i]) < meets.size() && meets[static_cast<size_t>(label[i])];
  }
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int count = 0;
  for (size_t i = 0; i < n; ++i)
    if (taken[i]) sum += now.position[i] - field.displacement[i], ++count;
  return count > 0 ? Eigen::Vector3d(sum / count) : fallback;
}

}  // namespace onetip::pose
