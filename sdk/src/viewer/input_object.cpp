#include "viewer/input_object.hpp"

#include <array>
#include <cmath>

#include "core/rotation.hpp"

namespace onetip::viewer {

Eigen::Isometry3d inputObjectPose(const Input6& v, double translation_gain) {
  return rigidFromTranslationYawPitchRoll(translation_gain * Eigen::Vector3d(v.dx, v.dy, -v.dz), v.yaw * kRadPerDeg,
                                          v.pitch * kRadPerDeg, v.roll * kRadPerDeg);
}

MeshVertices fingerBox(const Eigen::Vector3d& size_mm) {
  const Eigen::Vector3f h = (0.5 * size_mm).cast<float>();
  const Eigen::Vector3f centre(0.0F, 0.0F, h.z());
  MeshVertices mesh;
  // Each face: its outward normal, two in-plane axes, colour.
  struct Face {
    Eigen::Vector3f normal, u, v;
    Rgba colour;
  };
  const Rgba orange(1.0F, 0.55F, 0.1F, 1.0F), grey(0.75F, 0.75F, 0.78F, 1.0F), red(0.85F, 0.25F, 0.25F, 1.0F),
      blue(0.25F, 0.45F, 0.95F, 1.0F);
  const std::array<Face, 6> faces{{{-Eigen::Vector3f::UnitZ(), Eigen::Vector3f::UnitX(), Eigen::Vector3f::UnitY(), orange},
                                   {Eigen::Vector3f::UnitZ(), Eigen::Vector3f::UnitX(), Eigen::Vector3f::UnitY(), grey},
                                   {Eigen::Vector3f::UnitX(), Eigen::Vector3f::UnitY(), Eigen::Vector3f::UnitZ(), red},
                                   {-Eigen::Vector3f::UnitX(), Eigen::Vector3f::UnitY(), Eigen::Vector3f::UnitZ(), red},
                                   {Eigen::Vector3f::UnitY(), Eigen::Vector3f::UnitX(), Eigen::Vector3f::UnitZ(), blue},
                                   {-Eigen::Vector3f::UnitY(), Eigen::Vector3f::UnitX(), Eigen::Vector3f::UnitZ(), blue}}};
  for (const Face& face : faces) {
    const auto base = static_cast<unsigned>(mesh.count());
    const Eigen::Vector3f n = face.normal.cwiseProduct(h), u = face.u.cwiseProduct(h), v = face.v.cwiseProduct(h);
    for (const auto& [a, b] : std::array<std::pair<float, float>, 4>{{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}})
      mesh.add(centre + n + a * u + b * v, face.normal, face.colour, 0.0F);
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  return mesh;
}

PointVertices objectAxes(double length_mm) {
  const auto l = static_cast<float>(length_mm);
  PointVertices axes;
  axes.addLine({0, 0, 0}, {l, 0, 0}, {1.0F, 0.2F, 0.2F, 1.0F});
  axes.addLine({0, 0, 0}, {0, l, 0}, {0.2F, 1.0F, 0.2F, 1.0F});
  axes.addLine({0, 0, 0}, {0, 0, l}, {0.3F, 0.5F, 1.0F, 1.0F});
  return axes;
}

PointVertices padGrid(double half_extent_mm, double step_mm) {
  const auto e = static_cast<float>(half_extent_mm);
  const int lines = static_cast<int>(std::floor(half_extent_mm / step_mm));
  const Rgba colour(0.4F, 0.4F, 0.45F, 1.0F);
  PointVertices grid;
  for (int k = -lines; k <= lines; ++k) {
    const auto s = static_cast<float>(k * step_mm);
    grid.addLine({-e, s, 0}, {e, s, 0}, colour);
    grid.addLine({s, -e, 0}, {s, e, 0}, colour);
  }
  return grid;
}

}  // namespace onetip::viewer
