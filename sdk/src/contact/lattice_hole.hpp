// contact/lattice_hole.hpp — a marker the lattice does not measure, read from its grid neighbours.
//
// A marker hidden for good (a tear or dirt in the skin, sim/marker_damage.hpp)
// or lost for a frame leaves a hole in the lattice. A sum over the lattice that
// skips it (the footprint centre, contact/footprint_centre.hpp) weighs the
// surface around the hole by one cell less on one side: a dimple sliding past a
// hole 2 pitches off its path pulls its centre away from the hole while it
// passes, and the footprint reads a sideways motion the finger never made.
// The hole's estimate is the lattice's interpolant along each grid direction
// (along the row, along the column) whose neighbours on either side are
// measured: the cubic through the four at -2, -1, +1, +2 pitches,
//   x_i = (-x_{i-2d} + 4 x_{i-d} + 4 x_{i+d} - x_{i+2d}) / 6,
// or, where only the nearest two are measured, their midpoint; the mean over
// the directions, the same for the position p (S, mm) and the deformation
// u = p - rest (mm). The cubic is exact on any surface cubic along the
// direction (a dimple's cap is locally quadratic); the midpoint falls short of
// a curved dimple by pitch^2 / 2 times its curvature. It is the same rule in
// every frame, so a hole carried along by the gel moves the sum as the surface
// around it does, not as the hole does.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace onetip::contact {

struct LatticeSample {
  Eigen::Vector3d position{0, 0, 0};      // S, mm
  Eigen::Vector3d displacement{0, 0, 0};  // u = p - rest, mm
};

// The interpolant at marker `id` of a rows x cols lattice (id = row * cols + col)
// from the markers flagged in `measured`; false when neither direction has both
// neighbours measured (a border or a larger hole).
bool latticeInterpolant(int rows, int cols, int id, const std::vector<Eigen::Vector3d>& position,
                        const std::vector<Eigen::Vector3d>& displacement, const std::vector<std::uint8_t>& measured,
                        LatticeSample& out);

}  // namespace onetip::contact
