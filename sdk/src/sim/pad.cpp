#include "sim/pad.hpp"

#include <cmath>

#include "core/error.hpp"

namespace onetip::sim {

std::string_view toString(ContactModelKind kind) noexcept {
  return kind == ContactModelKind::foundation ? "foundation" : "halfspace";
}

std::optional<ContactModelKind> contactModelFromString(std::string_view name) noexcept {
  if (name == "halfspace") return ContactModelKind::halfspace;
  if (name == "foundation") return ContactModelKind::foundation;
  return std::nullopt;
}

void PadOptions::validate() const {
  pattern.validate();
  if (!(thickness_mm > 0.5) || thickness_mm > 100) throw InputError("pad: thickness_mm: must be in (0.5, 100]");
  if (pattern.marker_depth_mm >= thickness_mm) throw InputError("pad: marker_depth_mm: must be below thickness_mm");
  if (dome_radius_mm < 0 || !std::isfinite(dome_radius_mm))
    throw InputError("pad: dome_radius_mm: must be >= 0 (0 = flat)");
  const double half_extent = 0.5 * pattern.square_mm * (std::max(pattern.rows, pattern.cols) + 2 * margin_squares);
  if (dome_radius_mm > 0 && dome_radius_mm < 1.5 * half_extent)
    throw InputError("pad: dome_radius_mm: too small for the pad (needs >= 1.5 x its half-width)");
  if (nodes_per_square < 1 || nodes_per_square > 8) throw InputError("pad: nodes_per_square: must be in 1..8");
  if (margin_squares < 1 || margin_squares > 10) throw InputError("pad: margin_squares: must be in 1..10");
  if (!(friction > 0) || friction > 5) throw InputError("pad: friction: must be in (0, 5]");
  if (!(kinetic_ratio > 0 && kinetic_ratio <= 1)) throw InputError("pad: kinetic_ratio: must be in (0, 1]");
  if (!(foundation_length_mm >= 0 && foundation_length_mm <= 50))
    throw InputError("pad: foundation_length_mm: must be in [0, 50] mm (0: thickness / sqrt(3))");
}

PadLattice::PadLattice(const PadOptions& o) : options_(o) {
  o.validate();
  const MarkerPattern& p = o.pattern;
  h_ = p.square_mm / o.nodes_per_square;
  nu_ = (p.cols - 1 + 2 * o.margin_squares) * o.nodes_per_square + 1;
  nv_ = (p.rows - 1 + 2 * o.margin_squares) * o.nodes_per_square + 1;
  u0_ = -o.margin_squares * p.square_mm;
  v0_ = u0_;
  const double cx = 0.5 * (p.cols - 1) * p.square_mm, cy = 0.5 * (p.rows - 1) * p.square_mm;
  surface_.resize(static_cast<size_t>(nu_ * nv_));
  for (int b = 0; b < nv_; ++b)
    for (int a = 0; a < nu_; ++a) {
      const double x = u0_ + a * h_ - cx, y = v0_ + b * h_ - cy;
      surface_[static_cast<size_t>(nodeAt(a, b))] = {x, y, o.pattern.marker_depth_mm - domeOffset(x, y)};
    }
  marker_node_.resize(static_cast<size_t>(p.count()));
  for (int r = 0; r < p.rows; ++r)
    for (int c = 0; c < p.cols; ++c)
      marker_node_[static_cast<size_t>(p.id(r, c))] =
          nodeAt((c + o.margin_squares) * o.nodes_per_square, (r + o.margin_squares) * o.nodes_per_square);
}

double PadLattice::domeOffset(double x, double y) const {
  const double R = options_.dome_radius_mm;
  if (R <= 0) return 0.0;
  return R - std::sqrt(std::max(0.0, R * R - x * x - y * y));
}

Eigen::Vector3d PadLattice::markerLayerRest(int node) const {
  Eigen::Vector3d p = surfaceRest(node);
  p.z() -= options_.pattern.marker_depth_mm;
  return p;
}

}  // namespace onetip::sim
