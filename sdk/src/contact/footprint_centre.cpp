#include "contact/footprint_centre.hpp"

#include <algorithm>

namespace onetip::contact {

Eigen::Vector3d footprintCentre(const std::vector<Eigen::Vector3d>& positions,
                                const std::vector<double>& normal_deformation, double cut_mm) {
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero(), plain = Eigen::Vector3d::Zero();
  double weight = 0;
  for (size_t i = 0; i < positions.size(); ++i) {
    const double w = std::max(0.0, normal_deformation[i] - cut_mm);
    weighted += w * positions[i];
    weight += w;
    plain += positions[i];
  }
  if (weight > 0) return weighted / weight;
  return positions.empty() ? Eigen::Vector3d::Zero() : Eigen::Vector3d(plain / static_cast<double>(positions.size()));
}

}  // namespace onetip::contact
