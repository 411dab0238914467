// vision/grid_rescue.hpp — markers off their neighbours' motion that the
// lattice still places: the grid tracker's swap detector (grid_tracker.hpp)
// rejects a marker further than its tolerance from where its neighbours'
// motion puts it, but at a stick-slip edge a correct marker can be (it stuck
// while they jumped). Such a marker is taken back, in rounds (one taken back
// is a passing neighbour in the next), when its links to the passing
// neighbours neither flip, stretch nor cross and either
//  - it lies inside the cell of its four passing neighbours (cellMargin,
//    grid_checks.hpp: the only corner there is its own; open on the
//    pattern's border) and at most near_swap_squares from where one of three
//    models of the smooth field puts it (further is a near-swap): their
//    motion, their spatial completion (predictFromNeighbours over the
//    passing neighbours) or its own track (predictFromOwnTrack); at a
//    stick-slip edge the first misses by the jump, in a lattice sheared
//    within a cell the second, and at the onset of a slip the third, but a
//    detector's error of more than near_swap_squares is off all three where
//    the field is smooth (an error that happens to lie on the marker's own
//    track is not: that is the price of the third model); confidence 0.5; or
//  - every midpoint and parallelogram completion by those neighbours (at
//    least three, one a midpoint) puts it within rescue_fraction x spacing
//    (closeCompletion, grid_prediction.hpp); confidence 0.5 x (1 - that
//    distance / (rescue_fraction x spacing)).
// When no single marker can be taken back, two neighbouring ones that each
// lack the other as a vertex are taken back together when both lie inside
// the cell of the pair (pairCellMargins: their six neighbours' hexagon,
// holding their two corners alone), the right way round and each within
// near_swap_squares of one of those models; confidence 0.5 each.
// A marker on a neighbour's corner is a vertex of such a cell and a square
// from those completions; a region whose ids slipped together has no
// passing neighbours inside it. Units: view pixels; residuals in local
// spacings (squares).
#pragma once

#include <vector>

#include "core/pattern.hpp"
#include "vision/grid_prediction.hpp"
#include "vision/view_markers.hpp"

namespace onetip::vision {

constexpr float kNoTrack = 1e9f;  // OffMotion::track_squares of a marker whose motion is unknown

struct OffMotion {
  int id;
  float residual_squares;  // from where the neighbours' motion puts it, in local spacings
  float track_squares;     // from where its own track puts it (predictFromOwnTrack), or kNoTrack
};

struct RescueLimits {
  float rescue_fraction;           // of spacing: the completions' bound (GridTrackerOptions)
  float max_link_stretch;          // a link may grow or shrink by this factor per frame (GridTrackerOptions)
  float near_swap_squares = 0.4f;  // further from its place is a near-swap (issue 16's gross error)
};

// Erases the markers taken back from `reject` and sets their confidence.
// `m`: this frame's candidates; `before`: the last frame's markers; `spacing`:
// per id, the local spacing in pixels.
void rescueOffMotion(const MarkerPattern& pattern, const ViewMarkers& m, const LatticeView& before,
                     const std::vector<float>& spacing, const std::vector<OffMotion>& off_motion,
                     const RescueLimits& limits, std::vector<int>& reject, std::vector<float>& confidence);

}  // namespace onetip::vision
