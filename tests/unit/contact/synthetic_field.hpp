// tests/unit/contact/synthetic_field.hpp — flat marker grids in S with
// analytic deformations, for tests with a known answer.
#pragma once

#include <cmath>
#include <functional>

#include "core/marker_field.hpp"

namespace onetip::synth {

// rows x cols markers, `spacing` mm apart, centred on the origin, z = 0.
inline MarkerField flatGrid(int rows, int cols, double spacing = 1.2) {
  MarkerField f(rows, cols);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      f.set(r * cols + c, {(c - 0.5 * (cols - 1)) * spacing, (r - 0.5 * (rows - 1)) * spacing, 0.0});
  return f;
}

// Every valid marker moved by u(rest position).
inline MarkerField deformed(const MarkerField& rest, const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& u) {
  MarkerField f = rest;
  for (int i = 0; i < f.size(); ++i)
    if (f.valid[static_cast<size_t>(i)]) f.position[static_cast<size_t>(i)] += u(rest.position[static_cast<size_t>(i)]);
  return f;
}

// A Gaussian dimple of depth `depth` mm and width `width` mm centred at (x0, y0).
inline std::function<Eigen::Vector3d(const Eigen::Vector3d&)> dimple(double depth, double width, double x0 = 0,
                                                                      double y0 = 0) {
  return [=](const Eigen::Vector3d& p) {
    const double r2 = (p.x() - x0) * (p.x() - x0) + (p.y() - y0) * (p.y() - y0);
    return Eigen::Vector3d(0, 0, -depth * std::exp(-r2 / (width * width)));
  };
}

}  // namespace onetip::synth
