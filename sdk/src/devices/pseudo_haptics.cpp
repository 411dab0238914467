#include "devices/pseudo_haptics.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace onetip::devices {

double cdScaledDisplacement(double alpha, double real_displacement_mm, bool in_contact) {
  return in_contact ? alpha * real_displacement_mm : real_displacement_mm;
}

void PseudoHapticsOptions::validate() const {
  if (!(alpha > 0.0 && alpha <= 100.0)) throw InputError("PseudoHapticsOptions.alpha: must be in (0, 100]");
  if (!(max_device_force_n > 0.0 && std::isfinite(max_device_force_n)))
    throw InputError("PseudoHapticsOptions.max_device_force_n: must be positive");
  if (!(avatar_diameter_mm > 0.0 && std::isfinite(avatar_diameter_mm)))
    throw InputError("PseudoHapticsOptions.avatar_diameter_mm: must be positive");
  if (!(stiffness_scale > 0.0 && stiffness_scale <= 100.0))
    throw InputError("PseudoHapticsOptions.stiffness_scale: must be in (0, 100]");
}

PseudoHapticPlane::PseudoHapticPlane(const Eigen::Vector3d& point, const Eigen::Vector3d& outward_normal,
                                     const PseudoHapticsOptions& options)
    : point_(point), options_(options) {
  options_.validate();
  if (!(point.allFinite() && outward_normal.allFinite()) || outward_normal.norm() < 1e-12)
    throw InputError("PseudoHapticPlane: needs a finite point and a non-zero normal");
  normal_ = outward_normal.normalized();
}

PseudoHapticContact PseudoHapticPlane::update(const Eigen::Vector3d& c) const {
  PseudoHapticContact out;
  out.avatar_centre = c;
  const double radius = options_.avatar_diameter_mm / 2.0;
  const double penetration = radius - normal_.dot(c - point_);
  if (!(penetration > 0.0)) return out;
  out.in_contact = true;
  out.real_penetration_mm = penetration;
  out.virtual_penetration_mm = cdScaledDisplacement(options_.alpha, penetration, true);
  out.avatar_centre = c + (penetration - out.virtual_penetration_mm) * normal_;
  const double dx = options_.force_from_virtual ? out.virtual_penetration_mm : out.real_penetration_mm;
  const double force = options_.stiffness_scale * options_.baselineStiffness() * dx;
  out.saturated = force > options_.max_device_force_n;
  out.force_n = std::min(force, options_.max_device_force_n);
  return out;
}

}  // namespace onetip::devices
