#include "contact/surface_normals.hpp"

#include <Eigen/Geometry>

namespace onetip::contact {

namespace {

// Tangent along one grid direction (per grid step): the central difference,
// or next to a border or a lost marker the second-order one-sided difference
// (-3 p0 + 4 p1 - p2) / 2, or the first-order one as a last resort.
bool gridTangent(const MarkerField& f, int r, int c, int dr, int dc, Eigen::Vector3d& t) {
  auto validAt = [&](int k) {
    const int rr = r + k * dr, cc = c + k * dc;
    return rr >= 0 && rr < f.rows && cc >= 0 && cc < f.cols && f.valid[static_cast<size_t>(rr * f.cols + cc)];
  };
  auto at = [&](int k) -> const Eigen::Vector3d& {
    return f.position[static_cast<size_t>((r + k * dr) * f.cols + c + k * dc)];
  };
  if (validAt(1) && validAt(-1)) t = 0.5 * (at(1) - at(-1));
  else if (validAt(1) && validAt(2)) t = 0.5 * (-3 * at(0) + 4 * at(1) - at(2));
  else if (validAt(-1) && validAt(-2)) t = 0.5 * (3 * at(0) - 4 * at(-1) + at(-2));
  else if (validAt(1)) t = at(1) - at(0);
  else if (validAt(-1)) t = at(0) - at(-1);
  else return false;
  return true;
}

}  // namespace

void gridSurfaceNormals(const MarkerField& field, std::vector<Eigen::Vector3d>& normal,
                        std::vector<std::uint8_t>& normal_valid) {
  normal.assign(static_cast<size_t>(field.size()), Eigen::Vector3d::UnitZ());
  normal_valid.assign(static_cast<size_t>(field.size()), 0);
  for (int r = 0; r < field.rows; ++r)
    for (int c = 0; c < field.cols; ++c) {
      const size_t id = static_cast<size_t>(r * field.cols + c);
      if (!field.valid[id]) continue;
      Eigen::Vector3d tu, tv;
      if (!gridTangent(field, r, c, 0, 1, tu) || !gridTangent(field, r, c, 1, 0, tv)) continue;
      const Eigen::Vector3d n = tu.cross(tv);
      const double len = n.norm();
      if (!(len > 1e-12)) continue;
      normal[id] = n / len;
      normal_valid[id] = 1;
    }
}

}  // namespace onetip::contact
