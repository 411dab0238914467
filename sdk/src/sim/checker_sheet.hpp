// sim/checker_sheet.hpp — a deformable sheet printed with a checkerboard,
// the thing the simulator's renderer draws.
//
// Pattern coordinates (u, v) in mm: inner corner (row, col) sits at
// (u, v) = (col * square_mm, row * square_mm). The printed board covers
// u in [-square_mm, cols * square_mm] and v likewise with rows: (cols+1) x
// (rows+1) squares; the square with lower-left corner (i, j) * square_mm is
// dark when i + j is even. Around the board a light border of border_mm, and
// beyond it the sheet (if any) is background grey.
//
// The sheet's shape is a regular lattice of nu x nv vertices in (u, v):
// vertex (a, b) has (u, v) = (u0 + a * spacing_mm, v0 + b * spacing_mm) and
// 3-D position position[b * nu + a] in the sensor frame S (mm).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace onetip::sim {

struct CheckerTexture {
  int rows = 17;              // inner corners along v
  int cols = 17;              // inner corners along u
  double square_mm = 1.2;
  double border_mm = 1.2;     // light margin around the outer squares
  double dark = 40.0;         // grey levels before exposure and noise
  double light = 210.0;
  double background = 90.0;   // sheet beyond the border
};

struct CheckerSheet {
  CheckerTexture texture;
  int nu = 0, nv = 0;
  double u0 = 0, v0 = 0, spacing_mm = 0.15;
  std::vector<Eigen::Vector3d> position;  // nu * nv vertices, in S

  const Eigen::Vector3d& at(int a, int b) const { return position[static_cast<size_t>(b * nu + a)]; }
};

}  // namespace onetip::sim
