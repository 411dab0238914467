// vision/grid_recovery.hpp — lost markers found again through the board's
// rigid links.
//
// When a marker is lost (occluded, or it moved further than the local search
// reaches), its prediction can be several pixels off. The grid graph
// (vision/grid_graph.hpp) of the corners detected in the frame labels them
// with lattice coordinates up to an offset; the corners that already carry a
// tracked id vote for that offset (row_id - row_label, col_id - col_label).
// With a clear majority (at least 3 votes and 80% of them), each labelled
// corner that is not yet tracked gets id = label + offset, if that id is lost
// and the corner lies within max_distance[id] of its prediction. A corner
// matches a tracked marker when within 0.5 px of it.
// relabelAnchored (the fallback when tracking has nothing to grow from): all
// corners labelled through their links, and the lattice offset of that
// labelling chosen among those that keep it inside the pattern as the one
// whose corners lie nearest the markers' last positions (median distance
// over the labelled corners, so the part of the pattern that did not move,
// its border, decides); accepted when that median is below max_median_px.
// relabelByMajority (repairs a region whose ids slipped by a whole square,
// which no local test sees because its markers agree with each other): the
// corners' grid-graph labelling is compared with the markers' ids; every
// marker on a labelled corner (within 0.5 px) votes for the offset id - label;
// with at least half the votes and 3, every labelled corner gets
// id = label + offset, and markers that disagree with it are moved or
// cleared. Returns the number of ids whose position changed.
// Units: view pixels.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "core/pattern.hpp"
#include "vision/corner_detector.hpp"
#include "vision/view_markers.hpp"

namespace onetip::vision {

// corners in view coordinates of `view`; returns the number of markers added.
int recoverThroughLinks(const std::vector<Corner>& corners, const ViewHalf& view, const MarkerPattern& pattern,
                        const std::vector<cv::Point2f>& predicted, const std::vector<float>& max_distance,
                        ViewMarkers& markers);

int relabelByMajority(const std::vector<Corner>& corners, const ViewHalf& view, const MarkerPattern& pattern,
                      ViewMarkers& markers);

// Fills `markers` (all invalid on entry) from `corners`; returns the markers set.
int relabelAnchored(const std::vector<Corner>& corners, const ViewHalf& view, const MarkerPattern& pattern,
                    const std::vector<cv::Point2f>& last, float max_median_px, ViewMarkers& markers);

}  // namespace onetip::vision
