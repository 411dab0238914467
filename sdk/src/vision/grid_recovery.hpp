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
// matches a tracked marker when within 0.5 px of it. Units: view pixels.
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

}  // namespace onetip::vision
