// contact/grid_components.hpp — connected components of a mask on the marker grid.
//
// Cells (row, col) of a rows x cols grid, id = row * cols + col. Two masked
// cells are connected when they are 8-neighbours (a diagonal step counts, so
// a region missing a marker or two stays one region).
#pragma once

#include <cstdint>
#include <vector>

namespace onetip::contact {

// Component label per cell (-1 where the mask is 0), components numbered
// from 0 by decreasing size (ties: smaller first id first).
std::vector<int> labelGridComponents(int rows, int cols, const std::vector<std::uint8_t>& mask,
                                     int* component_count);
// The same, where two masked cells connect only when their `group` (per cell)
// is the same: the components of each group's cells at once.
std::vector<int> labelGridComponents(int rows, int cols, const std::vector<std::uint8_t>& mask,
                                     const std::vector<int>& group, int* component_count);

// Renumbers labels in place (any values in [0, label.size()), -1 for none)
// from 0 by decreasing size, ties: the label whose first cell comes first.
// Returns the number of labels.
int rankLabelsBySize(std::vector<int>& label);

}  // namespace onetip::contact
