#include "pose/contact_snapshot.hpp"

#include <cstdint>

#include "contact/footprint_centre.hpp"

namespace onetip::pose {

CommonFootprints commonFootprints(const ContactSnapshot& before, const contact::ContactField& field,
                                  const std::vector<int>& members, const MarkerField& now) {
  std::vector<std::uint8_t> used(static_cast<size_t>(now.size()), 0);
  for (int id : members) used[static_cast<size_t>(id)] = 1;
  for (int id : before.members) used[static_cast<size_t>(id)] = 1;
  std::vector<Eigen::Vector3d> p0, p1;
  std::vector<double> n0, n1;
  CommonFootprints out;
  for (size_t i = 0; i < used.size(); ++i) {
    if (!used[i] || !before.markers.valid[i] || !now.valid[i] || !field.valid[i]) continue;
    p0.push_back(before.markers.position[i]);
    n0.push_back(-before.displacement[i].z());
    p1.push_back(now.position[i]);
    n1.push_back(-field.displacement[i].z());
    out.depth_before += n0.back();
    out.depth_after += n1.back();
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
