#include "sim/rest_drift.hpp"

#include <cmath>

#include "core/option_checks.hpp"

namespace onetip::sim {

double RestDriftOptions::progress(double t) const { return 1 - std::exp(-std::max(t, 0.0) / time_s); }

Eigen::Vector3d RestDriftOptions::apply(const Eigen::Vector3d& p, double t) const {
  const double g = progress(t);
  const double scale = 1 + expansion * g;
  return Eigen::Vector3d(scale * p.x(), scale * p.y(), p.z()) + g * offset_mm;
}

void RestDriftOptions::validate() const {
  requireInRange("drift: expansion", expansion, -0.02, 0.02);
  requireInRange("drift: offset_mm[0]", offset_mm.x(), -1, 1, "mm");
  requireInRange("drift: offset_mm[1]", offset_mm.y(), -1, 1, "mm");
  requireInRange("drift: offset_mm[2]", offset_mm.z(), -1, 1, "mm");
  requireInRange("drift: time_s", time_s, 1, 7200, "s");
}

}  // namespace onetip::sim
