#include "devices/wire_device_geometry.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/rotation.hpp"

namespace onetip::devices {
namespace {
constexpr double kVertexAnglesDeg[3] = {90.0, 210.0, 330.0};
Eigen::Vector3d onCircle(double radius, int i) {
  const double a = kVertexAnglesDeg[i] * kRadPerDeg;
  return {radius * std::cos(a), radius * std::sin(a), 0.0};
}
}  // namespace

void WireDeviceGeometry::validate() const {
  if (!(body_radius_mm > 0.0 && body_radius_mm < 100.0)) throw InputError("WireDeviceGeometry.body_radius_mm: must be in (0, 100)");
  if (!(plate_radius_mm > 0.0 && plate_radius_mm < body_radius_mm))
    throw InputError("WireDeviceGeometry.plate_radius_mm: must be in (0, body_radius_mm) so the cables slant");
  if (!(initial_height_mm > 0.0 && initial_height_mm < 100.0))
    throw InputError("WireDeviceGeometry.initial_height_mm: must be in (0, 100)");
  if (!(spring_n_per_mm >= 0.0 && spring_n_per_mm < 10.0)) throw InputError("WireDeviceGeometry.spring_n_per_mm: must be in [0, 10)");
  if (!(fingertip_k > 0.0 && fingertip_k < 100.0)) throw InputError("WireDeviceGeometry.fingertip_k: must be in (0, 100)");
}

Eigen::Vector3d WireDeviceGeometry::bodyVertex(int i) const { return onCircle(body_radius_mm, i); }
Eigen::Vector3d WireDeviceGeometry::plateVertex(int i) const { return onCircle(plate_radius_mm, i); }

double WireDeviceGeometry::deformationFromForce(double f_fsr_n) const {
  return f_fsr_n > 0.0 ? std::sqrt(f_fsr_n / fingertip_k) : 0.0;
}

WireConfiguration wireConfiguration(const WireDeviceGeometry& g, const Eigen::Matrix3d& R, double hz_mm) {
  WireConfiguration c;
  const Eigen::Vector3d h(0.0, 0.0, -g.initial_height_mm + hz_mm);
  const Eigen::Vector3d h_rest(0.0, 0.0, -g.initial_height_mm);
  for (int i = 0; i < 3; ++i) {
    c.lever[i] = R * g.plateVertex(i);
    const Eigen::Vector3d l = g.bodyVertex(i) - (c.lever[i] + h);
    const double rest_length = (g.bodyVertex(i) - (g.plateVertex(i) + h_rest)).norm();
    c.length(i) = l.norm();
    c.G.col(i) = l / c.length(i);
    c.x(i) = rest_length - c.length(i);
  }
  return c;
}

}  // namespace onetip::devices
