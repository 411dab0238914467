// vision/grid_graph.hpp — lattice coordinates for detected checkerboard
// corners from the board's rigid links.
//
// Links: from each corner, along each of its two edge lines in both senses,
// the nearest corner within link_cone_deg of that direction; a link is kept
// when it is mutual, the two corners have opposite colour (the dark-sector
// bisector of one is within 45 deg of the light-sector bisector of the other,
// as the neighbour along an edge always has), and the link runs along an edge
// between a dark and a light square: at 1/4, 1/2 and 3/4 of its length, the
// image a quarter of the length to either side differs by at least the
// corners' contrast (half the dark/light difference), with the same sign,
// which a link across the board's border or a gap fails. Of a corner's two
// links along one edge line, one longer than max_collinear_ratio x the other
// jumps a gap and is dropped. Labelling: breadth-first from a
// well-linked seed; each corner carries its own lattice axes (its edge lines,
// signed to agree with the corner it was reached from), so the axes follow
// rotation, shear and bending of the board. Corners reached with two different
// labels, and labels claimed twice, are dropped; the largest component wins.
// Where its extent exceeds the expected rows x cols (in either axis
// assignment), sparse outer lines (stray corners linked beyond the board) are
// trimmed.
// Orientation (docs/reference.md, in the image the corners are given in): the
// lattice axis whose mean step is more along image x is the column axis, col
// grows with +x and row with +y; labels start at 0. If that would make the
// extent the transpose of the expected rows x cols, the axes are swapped
// keeping the image's handedness (col along +y, row along -x).
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "vision/corner_detector.hpp"

namespace onetip::vision {

struct GridLabelling {
  std::vector<int> row, col;  // per corner; -1 where not in the grid
  int rows = 0, cols = 0;     // extent of the labelled grid
  int labelled = 0;           // corners with a label
};

struct GridGraphOptions {
  float link_cone_deg = 25.0f;  // a neighbour must lie this close to an edge direction
  float max_collinear_ratio = 1.7f;  // of a corner's two collinear links, a longer one by this is dropped
  void validate() const;        // throws InputError naming the bad field
};

// corners in view coordinates of `view` (whose raw image is sampled).
GridLabelling labelGrid(const std::vector<Corner>& corners, const ViewHalf& view, int expected_rows,
                        int expected_cols, const GridGraphOptions& options = {});

}  // namespace onetip::vision
