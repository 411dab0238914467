// tests/unit/sim/render_test_sheets.hpp — analytic pad sheets for the
// renderers' tests and benchmark, and the effect-free ImageEffects.
//
// The pad is a lattice in the sensor frame S (mm) covering +-13 mm around
// the pattern centre, which sits at the S origin: pattern (u, v) maps to
// S (x, y) = (u - uc, v - vc) with (uc, vc) the centre of the inner corners.
// The lattice origin is a multiple of the spacing so that, when the spacing
// divides the square size, every inner corner is a lattice vertex.
// `deformedPoint` is a smooth Gaussian dent (1.5 mm towards the camera, 3 mm
// sigma) with a lateral shear of (0.5, 0.3) mm and a 10 degree twist, all
// weighted by the same Gaussian centred at (1.5, -1.0) mm.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <numbers>

#include "sim/checker_sheet.hpp"
#include "sim/renderer.hpp"

namespace onetip::sim::testsupport {

using SheetShape = std::function<Eigen::Vector3d(double x, double y)>;

inline Eigen::Vector3d restPoint(double x, double y) { return {x, y, 0.0}; }

inline Eigen::Vector3d deformedPoint(double x, double y) {
  const Eigen::Vector2d centre(1.5, -1.0), p(x, y);
  const double g = std::exp(-(p - centre).squaredNorm() / (2 * 3.0 * 3.0));
  const Eigen::Vector2d twisted = centre + Eigen::Rotation2Dd(10.0 * std::numbers::pi / 180 * g) * (p - centre);
  const Eigen::Vector2d moved = twisted + g * Eigen::Vector2d(0.5, 0.3);
  return {moved.x(), moved.y(), -1.5 * g};
}

// The S position (before the shape) of pattern point (u, v).
inline Eigen::Vector2d patternToPlane(const CheckerTexture& t, double u, double v) {
  return {u - 0.5 * (t.cols - 1) * t.square_mm, v - 0.5 * (t.rows - 1) * t.square_mm};
}

inline CheckerSheet padSheet(const SheetShape& shape, double spacing_mm = 0.15, double half_extent_mm = 13.0) {
  CheckerSheet s;
  const double uc = 0.5 * (s.texture.cols - 1) * s.texture.square_mm;
  const double vc = 0.5 * (s.texture.rows - 1) * s.texture.square_mm;
  s.spacing_mm = spacing_mm;
  s.u0 = -spacing_mm * std::ceil((half_extent_mm - uc) / spacing_mm);
  s.v0 = -spacing_mm * std::ceil((half_extent_mm - vc) / spacing_mm);
  s.nu = static_cast<int>(std::ceil((uc + half_extent_mm - s.u0) / spacing_mm)) + 1;
  s.nv = static_cast<int>(std::ceil((vc + half_extent_mm - s.v0) / spacing_mm)) + 1;
  s.position.reserve(static_cast<size_t>(s.nu) * static_cast<size_t>(s.nv));
  for (int b = 0; b < s.nv; ++b)
    for (int a = 0; a < s.nu; ++a) {
      const Eigen::Vector2d p = patternToPlane(s.texture, s.u0 + a * spacing_mm, s.v0 + b * spacing_mm);
      s.position.push_back(shape(p.x(), p.y()));
    }
  return s;
}

// No effects at all, not even sensor noise.
inline ImageEffects noEffects() {
  ImageEffects e;
  e.noise_sigma = 0;
  return e;
}

}  // namespace onetip::sim::testsupport
