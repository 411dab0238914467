#include "pose/touching_markers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "pose/rigid_fit.hpp"

namespace onetip::pose {

namespace {

double normalDeformation(const contact::ContactField& field, size_t i) { return -field.displacement[i].z(); }

// The core (ids) spans an area: the smaller principal RMS extent of its lattice coordinates.
bool spansArea(const std::vector<int>& core, int cols, double min_pitches) {
  std::vector<Eigen::Vector3d> lattice;
  for (int id : core) lattice.emplace_back(id % cols, id / cols, 0.0);
  return lattice.size() >= 3 && planarSpread(lattice).x() >= min_pitches;
}

// Per member, whether it is not clearly convex (kept), and the concave core.
struct LaplacianScan {
  std::vector<std::uint8_t> not_convex;  // per marker id
  std::vector<int> core;
};

LaplacianScan scanLaplacian(const contact::ContactField& field, const std::vector<int>& members, int rows, int cols,
                            double sigma_mm) {
  LaplacianScan scan;
  scan.not_convex.assign(field.displacement.size(), 0);
  const double bound = 3.0 * std::sqrt(20.0) * sigma_mm;
  for (int id : members) {
    const int r = id / cols, c = id % cols;
    double laplacian = 0;
    int measured = 0;
    for (const auto& [dr, dc] : {std::pair{0, 1}, {0, -1}, {1, 0}, {-1, 0}}) {
      const int rr = r + dr, cc = c + dc;
      if (rr < 0 || cc < 0 || rr >= rows || cc >= cols) continue;
      const size_t j = static_cast<size_t>(rr * cols + cc);
      if (!field.valid[j]) continue;
      laplacian += normalDeformation(field, j) - normalDeformation(field, static_cast<size_t>(id)), ++measured;
    }
    scan.not_convex[static_cast<size_t>(id)] = measured < 4 || laplacian <= bound;
    if (measured == 4 && laplacian < -2.0 * bound) scan.core.push_back(id);
  }
  return scan;
}

bool latticeMatches(const contact::ContactField& field, int rows, int cols) {
  return rows > 0 && cols > 0 && static_cast<size_t>(rows) * static_cast<size_t>(cols) == field.displacement.size();
}

// The members not clearly convex and at least as deep as the core's shallowest marker.
std::vector<std::uint8_t> coreAndDeeper(const contact::ContactField& field, const std::vector<int>& members,
                                        const LaplacianScan& scan) {
  std::vector<std::uint8_t> kept = scan.not_convex;
  double shallowest = std::numeric_limits<double>::infinity();
  for (int id : scan.core) shallowest = std::min(shallowest, normalDeformation(field, static_cast<size_t>(id)));
  for (int id : members)
    if (normalDeformation(field, static_cast<size_t>(id)) < shallowest) kept[static_cast<size_t>(id)] = 0;
  return kept;
}

}  // namespace

std::vector<std::uint8_t> touchingMarkers(const contact::ContactField& field, const std::vector<int>& members, int rows,
                                          int cols, double sigma_mm, double core_spread_pitches) {
  if (!latticeMatches(field, rows, cols)) {
    std::vector<std::uint8_t> touching(field.displacement.size(), 0);
    for (int id : members) touching[static_cast<size_t>(id)] = 1;  // no lattice to judge by
    return touching;
  }
  const LaplacianScan scan = scanLaplacian(field, members, rows, cols, sigma_mm);
  if (core_spread_pitches <= 0 || !spansArea(scan.core, cols, core_spread_pitches)) return scan.not_convex;
  return coreAndDeeper(field, members, scan);
}

std::vector<std::uint8_t> capMarkers(const contact::ContactField& field, const std::vector<int>& members, int rows,
                                     int cols, double sigma_mm) {
  if (!latticeMatches(field, rows, cols)) return std::vector<std::uint8_t>(field.displacement.size(), 0);
  const LaplacianScan scan = scanLaplacian(field, members, rows, cols, sigma_mm);
  if (scan.core.empty()) return std::vector<std::uint8_t>(field.displacement.size(), 0);
  return coreAndDeeper(field, members, scan);
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
