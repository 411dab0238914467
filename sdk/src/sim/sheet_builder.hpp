// sim/sheet_builder.hpp — turns the contact model's node lattice (or a rigid
// target) into the fine CheckerSheet the renderer draws.
//
// The node lattice (spacing h, one node per marker by default) is refined by
// an integer factor with separable Catmull-Rom interpolation of the 3-D vertex
// positions: it passes exactly through every node (so every marker corner is
// rendered exactly where the ground truth says) and is C1 between them.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "sim/checker_sheet.hpp"

namespace onetip::sim {

// nodes: nu x nv positions (row-major, v rows), lattice origin (u0, v0), spacing h.
CheckerSheet refineLattice(const std::vector<Eigen::Vector3d>& nodes, int nu, int nv, double u0, double v0,
                           double h, int factor, const CheckerTexture& texture);

// A rigid flat board: corners (row, col) at pose * ((col - (cols-1)/2) sq, (row - (rows-1)/2) sq, 0),
// with a lattice covering the board and its border.
CheckerSheet rigidBoard(const CheckerTexture& texture, const Eigen::Isometry3d& pose, double spacing_mm);

}  // namespace onetip::sim
