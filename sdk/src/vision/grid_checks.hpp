// vision/grid_checks.hpp — consistency tests of a tracked marker lattice,
// for the grid tracker's swap detector (vision/grid_tracker.hpp).
//
// checkLinks: the links of (r, c) to its four neighbours, now against the
// last frame: bad where a link flips direction or changes length by more
// than `stretch` either way; crossed where two consecutive links (right,
// down, left, up) turn the other way round than they did.
// hasSeam: whether ids slipped by a square somewhere: two neighbouring ids on
// one corner (a link shorter than a tenth of both links that continue it
// along its lattice line), or a link longer than `stretch` x both of those
// with a corner at its middle (the corner the slipped ids skipped; the middle
// of a true link is the middle of a square's edge, where no corner can be).
// cellMargin: where p lies in the cell of (r, c), the quadrilateral of its
// four neighbours (right, down, left, up) in `grid`: for each edge, p's signed
// distance to it over that of the point the neighbours put (r, c) at (the
// mean of the opposite pairs' midpoints); the smallest of these. The ratio
// is invariant to any affine map of the lattice: the undistorted cell puts
// (r, c) at 1, a 4-neighbour's corner at 0 (a vertex) and a diagonal
// neighbour's at -1 (beyond an edge), every other corner further out. A
// checkerboard's image is a continuous one-to-one map of its lattice, so the
// only corner inside that cell is (r, c)'s own unless the lattice bends
// within the cell by enough to carry a diagonal neighbour across a straight
// edge (about 0.7 of a square against the affine map of its neighbours). On
// the pattern's border the cell is open on the side with no neighbour (no
// corner lies beyond the border): its two edges count.
// Nothing when a neighbour inside the pattern is missing from `grid` or the
// cell is not convex.
// Units: view pixels.
#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <utility>

#include "vision/grid_growth.hpp"
#include "vision/grid_prediction.hpp"
#include "vision/view_markers.hpp"

namespace onetip::vision {

struct LinkCheck {
  int checked = 0, bad = 0, crossed = 0;
};
LinkCheck checkLinks(const LatticeView& now, const LatticeView& before, int r, int c, float stretch);

std::optional<float> cellMargin(const LatticeView& grid, int r, int c, cv::Point2f p);

// pairCellMargins: the same for two neighbouring markers a = (r, c) and
// b = (r + dr, c + dc) (one step along a lattice axis) neither of which can
// use the other as a vertex: the cell of the pair is the hexagon of their six
// 4-neighbours, inside which lie a's and b's corners alone (undistorted:
// both at 2/3, every other corner at or below 0). The reference point is the
// pair's centre where their neighbours put it (the mean of the midpoints of
// the three opposite pairs across it); the margins of pa and pb, or nothing
// when a vertex inside the pattern is missing from `grid`, the hexagon is not
// convex, or pa and pb lie the wrong way round along the pair's axis.
std::optional<std::pair<float, float>> pairCellMargins(const LatticeView& grid, int r, int c, int dr, int dc,
                                                       cv::Point2f pa, cv::Point2f pb);

// near: the corner finder of the frame (grid_growth.hpp).
bool hasSeam(const ViewMarkers& m, float stretch, const CornerFinder& near);

}  // namespace onetip::vision
