#include "sim/indenter.hpp"

#include <cmath>

#include "core/error.hpp"

namespace onetip::sim {

void IndenterGeometry::validate() const {
  if (shape == IndenterShape::plate) {
    if (!(plate_width > 0) || !(plate_length > 0) || plate_width > 500 || plate_length > 500)
      throw InputError("indenter: plate size: width and length must be in (0, 500] mm");
  } else {
    for (int i = 0; i < 3; ++i)
      if (!(semi_axes[i] > 0.1) || semi_axes[i] > 200)
        throw InputError("indenter: semi_axes: each must be in (0.1, 200] mm");
  }
}

IndenterShape IndenterGeometry::shapeFromName(const std::string& name) {
  if (name == "ellipsoid" || name == "finger") return IndenterShape::ellipsoid;
  if (name == "sphere") return IndenterShape::sphere;
  if (name == "plate" || name == "flat") return IndenterShape::plate;
  throw InputError("indenter: shape: '" + name + "' is not one of ellipsoid, sphere, plate");
}

std::optional<double> lowerSurfaceZ(const IndenterGeometry& g, const Eigen::Isometry3d& pose,
                                    double x, double y) {
  // The vertical line X(z) = (x, y, z) in local coordinates is q0 + z * w.
  const Eigen::Matrix3d Rt = pose.linear().transpose();
  const Eigen::Vector3d q0 = Rt * (Eigen::Vector3d(x, y, 0) - pose.translation());
  const Eigen::Vector3d w = Rt.col(2);
  if (g.shape == IndenterShape::plate) {
    if (std::abs(w.z()) < 1e-9) return std::nullopt;
    const double z = -q0.z() / w.z();
    const Eigen::Vector3d hit = q0 + z * w;
    if (std::abs(hit.x()) > g.plate_width / 2 || std::abs(hit.y()) > g.plate_length / 2)
      return std::nullopt;
    return z;
  }
  const Eigen::Vector3d a = g.semi_axes;
  const Eigen::Vector3d inv2(1 / (a.x() * a.x()), 1 / (a.y() * a.y()), 1 / (a.z() * a.z()));
  const Eigen::Vector3d d = q0 - Eigen::Vector3d(0, 0, a.z());
  const double alpha = (w.array().square() * inv2.array()).sum();
  const double beta = (w.array() * d.array() * inv2.array()).sum();
  const double gamma = (d.array().square() * inv2.array()).sum() - 1.0;
  const double disc = beta * beta - alpha * gamma;
  if (disc < 0) return std::nullopt;
  return (-beta - std::sqrt(disc)) / alpha;
}

double lowestZ(const IndenterGeometry& g, const Eigen::Isometry3d& pose) {
  if (g.shape == IndenterShape::plate) {
    double lowest = INFINITY;
    for (int sx : {-1, 1})
      for (int sy : {-1, 1})
        lowest = std::min(lowest, (pose * Eigen::Vector3d(sx * g.plate_width / 2,
                                                          sy * g.plate_length / 2, 0)).z());
    return lowest;
  }
  // Support of the ellipsoid {R (m + diag(a) s) + p : |s| = 1} in direction -z.
  const Eigen::Vector3d centre = pose * Eigen::Vector3d(0, 0, g.semi_axes.z());
  const Eigen::Vector3d r = g.semi_axes.asDiagonal() * (pose.linear().transpose() * Eigen::Vector3d::UnitZ());
  return centre.z() - r.norm();
}

double footprintRadius(const IndenterGeometry& g) {
  if (g.shape == IndenterShape::plate) return 0.5 * std::hypot(g.plate_width, g.plate_length);
  return 2.0 * g.semi_axes.maxCoeff();
}

}  // namespace onetip::sim
