#include "pose/contact_snapshot.hpp"

#include <cstdint>
#include <utility>

#include "contact/footprint_centre.hpp"
#include "contact/lattice_hole.hpp"

namespace onetip::pose {

namespace {

// Marker i of a rows x cols lattice, or a 4-neighbour of it, is flagged in `used`.
bool touchesUsed(const std::vector<std::uint8_t>& used, int rows, int cols, int i) {
  const int r = i / cols, c = i % cols;
  for (const auto& [dr, dc] : {std::pair{0, 0}, std::pair{0, 1}, std::pair{0, -1}, std::pair{1, 0}, std::pair{-1, 0}}) {
    const int rr = r + dr, cc = c + dc;
    if (rr >= 0 && rr < rows && cc >= 0 && cc < cols && used[static_cast<size_t>(rr * cols + cc)]) return true;
  }
  return false;
}

}  // namespace

CommonFootprints commonFootprints(const ContactSnapshot& before, const contact::ContactField& field,
                                  const std::vector<int>& members, const MarkerField& now) {
  const size_t count = static_cast<size_t>(now.size());
  std::vector<std::uint8_t> used(count, 0), measured(count, 0);  // measured: in both frames
  for (int id : members) used[static_cast<size_t>(id)] = 1;
  for (int id : before.members) used[static_cast<size_t>(id)] = 1;
  for (size_t i = 0; i < count; ++i) measured[i] = before.markers.valid[i] && now.valid[i] && field.valid[i];
  std::vector<Eigen::Vector3d> p0, p1;
  std::vector<double> n0, n1;
  CommonFootprints out;
  auto add = [&](const Eigen::Vector3d& q0, const Eigen::Vector3d& u0, const Eigen::Vector3d& q1,
                 const Eigen::Vector3d& u1) {
    p0.push_back(q0);
    n0.push_back(-u0.z());
    p1.push_back(q1);
    n1.push_back(-u1.z());
    out.depth_before += n0.back();
    out.depth_after += n1.back();
  };
  for (size_t i = 0; i < count; ++i) {
    if (measured[i]) {
      if (used[i]) add(before.markers.position[i], before.displacement[i], now.position[i], field.displacement[i]);
      continue;
    }
    // A hole in either frame at or beside the footprint: the lattice's estimate in both, from the neighbours
    // measured in both, so the same cells by the same rule enter both centres whichever frame lost the marker.
    contact::LatticeSample s0, s1;
    const int id = static_cast<int>(i);
    if (touchesUsed(used, now.rows, now.cols, id) &&
        contact::latticeInterpolant(now.rows, now.cols, id, before.markers.position, before.displacement, measured,
                                    s0) &&
        contact::latticeInterpolant(now.rows, now.cols, id, now.position, field.displacement, measured, s1))
      add(s0.position, s0.displacement, s1.position, s1.displacement);
  }
  if (p0.empty()) {
    out.before = out.after = before.footprint;
    return out;
  }
  out.before = contact::footprintCentre(p0, n0, before.cut_mm);
  out.after = contact::footprintCentre(p1, n1, field.cutOf(members));
  return out;
}

}  // namespace onetip::pose
