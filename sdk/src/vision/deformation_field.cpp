#include "vision/deformation_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace onetip::vision {

namespace {

void requireSameGrid(const MarkerField& a, const MarkerField& b, const char* what) {
  if (a.rows != b.rows || a.cols != b.cols || a.size() != static_cast<int>(a.position.size()) ||
      b.size() != static_cast<int>(b.position.size()))
    throw InputError(std::string("deformation field: ") + what + ": marker grids differ in size");
}

// Barycentric blend of v[0..2] at q inside triangle p[0..2]; false outside.
bool blend(const Eigen::Vector2d (&p)[3], const Eigen::Vector3d* const (&v)[3],
           const Eigen::Vector2d& q, Eigen::Vector3d& out) {
  const Eigen::Vector2d e1 = p[1] - p[0], e2 = p[2] - p[0], w = q - p[0];
  const double det = e1.x() * e2.y() - e1.y() * e2.x();
  if (std::abs(det) < 1e-12) return false;
  const double b1 = (w.x() * e2.y() - w.y() * e2.x()) / det;
  const double b2 = (e1.x() * w.y() - e1.y() * w.x()) / det;
  const double b0 = 1.0 - b1 - b2;
  constexpr double tol = -1e-9;
  if (b0 < tol || b1 < tol || b2 < tol) return false;
  out = b0 * *v[0] + b1 * *v[1] + b2 * *v[2];
  return true;
}

}  // namespace

MarkerField markerDisplacement(const MarkerField& now, const MarkerField& rest) {
  requireSameGrid(now, rest, "now vs rest");
  MarkerField d(rest.rows, rest.cols);
  for (int i = 0; i < rest.size(); ++i)
    if (now.valid[static_cast<size_t>(i)] && rest.valid[static_cast<size_t>(i)])
      d.set(i, now.position[static_cast<size_t>(i)] - rest.position[static_cast<size_t>(i)]);
  return d;
}

void DisplacementGridOptions::validate() const {
  if (!(spacing_mm > 0.0) || !std::isfinite(spacing_mm))
    throw InputError("displacement grid: spacing_mm: must be a positive number");
}

DisplacementGrid interpolateDisplacement(const MarkerField& rest, const MarkerField& displacement,
                                         const DisplacementGridOptions& options) {
  options.validate();
  requireSameGrid(rest, displacement, "rest vs displacement");
  const auto ok = [&](int r, int c) {
    const auto i = static_cast<size_t>(r * rest.cols + c);
    return rest.valid[i] && displacement.valid[i];
  };
  double lo_x = std::numeric_limits<double>::max(), lo_y = lo_x;
  double hi_x = std::numeric_limits<double>::lowest(), hi_y = hi_x;
  for (int i = 0; i < rest.size(); ++i)
    if (rest.valid[static_cast<size_t>(i)]) {
      const Eigen::Vector3d& p = rest.position[static_cast<size_t>(i)];
      lo_x = std::min(lo_x, p.x());
      lo_y = std::min(lo_y, p.y());
      hi_x = std::max(hi_x, p.x());
      hi_y = std::max(hi_y, p.y());
    }
  DisplacementGrid g;
  g.spacing_mm = options.spacing_mm;
  g.x0_mm = lo_x;
  g.y0_mm = lo_y;
  g.nx = static_cast<int>(std::floor((hi_x - lo_x) / options.spacing_mm + 1e-9)) + 1;
  g.ny = static_cast<int>(std::floor((hi_y - lo_y) / options.spacing_mm + 1e-9)) + 1;
  if (!(g.nx > 0 && g.ny > 0) || static_cast<double>(g.nx) * g.ny > 1e8)
    throw InputError("displacement grid: spacing_mm is too small for the pad's extent");
  g.displacement.assign(static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny), Eigen::Vector3d::Zero());
  g.valid.assign(g.displacement.size(), 0);

  int cells = 0;
  for (int r = 0; r + 1 < rest.rows; ++r)
    for (int c = 0; c + 1 < rest.cols; ++c) {
      if (!ok(r, c) || !ok(r, c + 1) || !ok(r + 1, c) || !ok(r + 1, c + 1)) continue;
      ++cells;
      const int ids[2][3] = {{r * rest.cols + c, r * rest.cols + c + 1, (r + 1) * rest.cols + c + 1},
                             {r * rest.cols + c, (r + 1) * rest.cols + c + 1, (r + 1) * rest.cols + c}};
      for (const auto& tri : ids) {
        Eigen::Vector2d p[3];
        const Eigen::Vector3d* v[3];
        double bx0 = 1e300, by0 = 1e300, bx1 = -1e300, by1 = -1e300;
        for (int k = 0; k < 3; ++k) {
          const auto id = static_cast<size_t>(tri[k]);
          p[k] = rest.position[id].head<2>();
          v[k] = &displacement.position[id];
          bx0 = std::min(bx0, p[k].x());
          by0 = std::min(by0, p[k].y());
          bx1 = std::max(bx1, p[k].x());
          by1 = std::max(by1, p[k].y());
        }
        const int ix0 = std::max(0, static_cast<int>(std::ceil((bx0 - g.x0_mm) / g.spacing_mm - 1e-9)));
        const int iy0 = std::max(0, static_cast<int>(std::ceil((by0 - g.y0_mm) / g.spacing_mm - 1e-9)));
        const int ix1 = std::min(g.nx - 1, static_cast<int>(std::floor((bx1 - g.x0_mm) / g.spacing_mm + 1e-9)));
        const int iy1 = std::min(g.ny - 1, static_cast<int>(std::floor((by1 - g.y0_mm) / g.spacing_mm + 1e-9)));
        for (int iy = iy0; iy <= iy1; ++iy)
          for (int ix = ix0; ix <= ix1; ++ix) {
            const size_t n = g.index(ix, iy);
            if (g.valid[n]) continue;
            if (blend(p, v, g.node(ix, iy), g.displacement[n])) g.valid[n] = 1;
          }
      }
    }
  if (cells == 0)
    throw InputError("displacement grid: no grid cell has all four corners measured");
  return g;
}

}  // namespace onetip::vision
