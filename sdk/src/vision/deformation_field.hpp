// vision/deformation_field.hpp — how far each marker has moved since rest.
//
// markerDisplacement: per marker id, d = now - rest (both in the same frame,
// normally the sensor frame S; mm), valid where both are valid.
// interpolateDisplacement: the per-marker field resampled on a regular grid in
// the S x-y plane (the pad plane). Each rest-grid cell whose four corners are
// valid is split into two triangles along its (row, col)-(row+1, col+1)
// diagonal; a grid node inside a triangle (in the rest positions' x-y
// projection) gets the barycentric blend of the three corners' displacements,
// so a displacement that varies linearly across the pad is reproduced exactly.
// Nodes outside every such triangle are invalid. The grid starts at the lower
// corner of the valid rest markers' x-y bounding box and steps spacing_mm.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/marker_field.hpp"

namespace onetip::vision {

// now - rest per marker; throws InputError when the grids differ in size.
MarkerField markerDisplacement(const MarkerField& now, const MarkerField& rest);

struct DisplacementGridOptions {
  double spacing_mm = 0.5;
  void validate() const;  // throws InputError naming the bad field
};

struct DisplacementGrid {
  double x0_mm = 0.0, y0_mm = 0.0;  // S coordinates of node (0, 0)
  double spacing_mm = 0.0;
  int nx = 0, ny = 0;
  std::vector<Eigen::Vector3d> displacement;  // row-major, ny x nx, mm
  std::vector<std::uint8_t> valid;

  Eigen::Vector2d node(int ix, int iy) const {
    return {x0_mm + ix * spacing_mm, y0_mm + iy * spacing_mm};
  }
  size_t index(int ix, int iy) const { return static_cast<size_t>(iy) * static_cast<size_t>(nx) + static_cast<size_t>(ix); }
};

// rest: rest positions in S (their x, y place the markers on the plane);
// displacement: from markerDisplacement. Throws InputError when the grids
// differ in size or fewer than one full cell is valid.
DisplacementGrid interpolateDisplacement(const MarkerField& rest, const MarkerField& displacement,
                                         const DisplacementGridOptions& options = {});

}  // namespace onetip::vision
