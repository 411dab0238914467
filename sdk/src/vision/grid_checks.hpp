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
// Units: view pixels.
#pragma once

#include <opencv2/core.hpp>

#include "vision/grid_growth.hpp"
#include "vision/grid_prediction.hpp"
#include "vision/view_markers.hpp"

namespace onetip::vision {

struct LinkCheck {
  int checked = 0, bad = 0, crossed = 0;
};
LinkCheck checkLinks(const LatticeView& now, const LatticeView& before, int r, int c, float stretch);

// near: the corner finder of the frame (grid_growth.hpp).
bool hasSeam(const ViewMarkers& m, float stretch, const CornerFinder& near);

}  // namespace onetip::vision
