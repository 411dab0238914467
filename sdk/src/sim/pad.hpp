// sim/pad.hpp — the simulated silicone pad: its node lattice and rest shape.
//
// The pad is a soft layer of thickness_mm bonded to a rigid transparent base.
// The checkerboard (the markers) lies in the dermis, pattern.marker_depth_mm
// below the outer surface. Flat by default; with dome_radius_mm > 0 both surfaces are
// spherical caps of that radius (apex at the centre).
//
// Lattice: nodes every h = square_mm / nodes_per_square in pattern coordinates
// (u, v) (CheckerSheet convention: inner corner (row, col) at (col, row) * square),
// from -margin_squares to (cols - 1 + margin_squares) squares, so every marker
// is a node. Node positions are given in the simulator's pad frame P:
// x = u - (cols-1) * square / 2, y = v - (rows-1) * square / 2 and, for a flat
// pad, the marker layer at z = 0 and the outer surface at z = pattern.marker_depth_mm.
// P equals the sensor frame S for a flat pad; for a domed pad S is derived
// from the rest markers as docs/reference.md says (Simulator does that).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "core/pattern.hpp"

namespace onetip::sim {

// The two contact models of the simulator (sim/contact_kernel.hpp has the maths).
// They differ on purpose in every part an estimator could be tuned to:
//   halfspace:  Boussinesq/Cerruti response of an incompressible elastic layer
//               (long-range 1/r kernel, tangential/normal compliance 1.5),
//               Coulomb friction with one coefficient;
//   foundation: Pasternak foundation (springs + a shear layer: short-range
//               K0(r/l) kernel, a flatter pressure distribution and a steeper
//               dip around the contact), compressible (tangential/normal
//               compliance 1.0), static/kinetic friction (a slipping point
//               carries kinetic_ratio x mu p and sticks again only below it).
enum class ContactModelKind : std::uint8_t { halfspace = 0, foundation };
std::string_view toString(ContactModelKind kind) noexcept;
std::optional<ContactModelKind> contactModelFromString(std::string_view name) noexcept;

struct PadOptions {
  MarkerPattern pattern;            // 17 x 17 inner corners, 1.2 mm squares, 0.3 mm below the surface
  double thickness_mm = 7.0;        // soft layer thickness (decay length of the elastic kernel)
  double dome_radius_mm = 0.0;      // 0: flat
  int nodes_per_square = 1;         // contact lattice nodes per marker spacing (1: one per marker)
  int margin_squares = 3;           // lattice beyond the outer markers
  double friction = 1.0;            // (static) Coulomb coefficient between finger and skin
  ContactModelKind contact_model = ContactModelKind::halfspace;
  double kinetic_ratio = 0.7;       // foundation model: kinetic / static friction, (0, 1]
  double foundation_length_mm = 0;  // foundation model: shear coupling length l; 0 = thickness / sqrt(3)
  void validate() const;            // throws InputError naming the bad field
};

class PadLattice {
 public:
  explicit PadLattice(const PadOptions& options);

  const PadOptions& options() const { return options_; }
  int nu() const { return nu_; }
  int nv() const { return nv_; }
  int nodeCount() const { return nu_ * nv_; }
  double spacing() const { return h_; }
  double u0() const { return u0_; }  // pattern coordinate of node column 0 (mm)
  double v0() const { return v0_; }

  // Rest position of a node's outer surface point and marker-layer point (P, mm).
  const Eigen::Vector3d& surfaceRest(int node) const { return surface_[static_cast<size_t>(node)]; }
  Eigen::Vector3d markerLayerRest(int node) const;
  // Lattice node of marker id (row * cols + col).
  int nodeOfMarker(int id) const { return marker_node_[static_cast<size_t>(id)]; }
  int nodeAt(int a, int b) const { return b * nu_ + a; }

  // Height of the rest marker layer below the surface point (x, y) in P.
  double domeOffset(double x, double y) const;

 private:
  PadOptions options_;
  int nu_ = 0, nv_ = 0;
  double h_ = 0, u0_ = 0, v0_ = 0;
  std::vector<Eigen::Vector3d> surface_;
  std::vector<int> marker_node_;
};

}  // namespace onetip::sim
