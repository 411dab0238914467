// contact/surface_normals.hpp — normals of the deformed marker layer from grid neighbours.
//
// For marker (row, col) of a MarkerField in S: the tangent along the columns
// t_u = p(row, col+1) - p(row, col-1) (a second-order one-sided difference at a
// border or next to a lost marker), t_v likewise along the rows, and
// n = normalize(t_u x t_v). Columns
// grow along S.x and rows along S.y, so n points out of the pad (+z at rest),
// towards the finger; it is also the finger's surface normal where they touch.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/marker_field.hpp"

namespace onetip::contact {

// Fills normal[i] (unit) and normal_valid[i] for every valid marker that has
// at least one valid neighbour along each grid direction.
void gridSurfaceNormals(const MarkerField& field, std::vector<Eigen::Vector3d>& normal,
                        std::vector<std::uint8_t>& normal_valid);

}  // namespace onetip::contact
