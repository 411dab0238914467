#include "pose/touching_markers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "pose/rigid_fit.hpp"

namespace onetip::pose {

namespace {

// The core (ids) spans an area: the smaller principal RMS extent of its lattice coordinates.
bool spansArea(const std::vector<int>& core, int cols, double min_pitches) {
  std::vector<Eigen::Vector3d> lattice;
  for (int id : core) lattice.emplace_back(id % cols, id / cols, 0.0);
  return lattice.size() >= 3 && planarSpread(lattice).x() >= min_pitches;
}

}  // namespace

std::vector<std::uint8_t> touchingMarkers(const contact::ContactField& field, const std::vector<int>& members, int rows,
                                          int cols, double sigma_mm, double core_spread_pitches) {
  std::vector<std::uint8_t> touching(field.displacement.size(), 0);
  if (rows <= 0 || cols <= 0 || static_cast<size_t>(rows) * static_cast<size_t>(cols) != touching.size()) {
    for (int id : members) touching[static_cast<size_t>(id)] = 1;  // no lattice to judge by
    return touching;
  }
  const double bound = 3.0 * std::sqrt(20.0) * sigma_mm;
  const auto normal = [&](size_t i) { return -field.displacement[i].z(); };
  std::vector<int> core;
  for (int id : members) {
    const int r = id / cols, c = id % cols;
    double laplacian = 0;
    int measured = 0;
    for (const auto& [dr, dc] : {std::pair{0, 1}, {0, -1}, {1, 0}, {-1, 0}}) {
      const int rr = r + dr, cc = c + dc;
      if (rr < 0 || cc < 0 || rr >= rows || cc >= cols) continue;
      const size_t j = static_cast<size_t>(rr * cols + cc);
      if (!field.valid[j]) continue;
      laplacian += normal(j) - normal(static_cast<size_t>(id)), ++measured;
    }
    touching[static_cast<size_t>(id)] = measured < 4 || laplacian <= bound;
    if (measured == 4 && laplacian < -2.0 * bound) core.push_back(id);
  }
  if (core_spread_pitches <= 0 || !spansArea(core, cols, core_spread_pitches)) return touching;
  double shallowest = std::numeric_limits<double>::infinity();
  for (int id : core) shallowest = std::min(shallowest, normal(static_cast<size_t>(id)));
  for (int id : members)
    if (normal(static_cast<size_t>(id)) < shallowest) touching[static_cast<size_t>(id)] = 0;
  return touching;
}

std::vector<int> detachedUnderTheFinger(const std::vector<int>& members, const std::vector<std::uint8_t>& touching,
                                        const std::vector<contact::MarkerLabel>& labels, const MarkerField& before,
                                        const MarkerField& now, int min_count) {
  std::vector<int> detached;
  int measured = 0, touched = 0;
  for (int id : members) {
    const size_t i = static_cast<size_t>(id);
    if (!now.valid[i]) continue;
    ++measured;
    if (!touching[i]) continue;
    ++touched;
    if (labels[i] == contact::MarkerLabel::stick) return {};
    if (labels[i] == contact::MarkerLabel::detached && before.valid[i]) detached.push_back(id);
  }
  if (touched == measured || static_cast<int>(detached.size()) < min_count) return {};
  return detached;
}

}  // namespace onetip::pose
