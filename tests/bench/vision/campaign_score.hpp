// tests/bench/vision/campaign_score.hpp — one view's tracked markers scored
// against the simulator's truth.
//
// Truth: each marker's exact 3-D position in S projected through the view's
// simulated camera (distortion included, view pixels after the flip). The
// local square in pixels is the median distance from a marker's true image to
// its true 4-neighbours'. A reported marker is correct when it lies within
// kGrossSquares (0.4) of a square of its truth and a gross error (a swap or a
// near-swap) beyond that. Markers closer than 12 px to the view's border are
// not counted as "in view".
// playRun: a campaign run rendered frame by frame, each view tracked by a
// vision::GridTracker (initialised on frame 0, the rest frame), scored per
// frame: motion_sq is the largest 3-D motion of any marker since the last
// frame in squares; contact_* count the markers whose node touches the finger
// in the truth and that lie in both views; *_found those reported within 0.4
// of a square of the truth in both views; gross the (marker, view) pairs
// reported beyond that.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "campaign_runs.hpp"
#include "core/marker_field.hpp"
#include "sim/camera_rig.hpp"
#include "vision/view_markers.hpp"

namespace onetip::bench {

constexpr double kGrossSquares = 0.4;

struct ViewScore {
  std::vector<std::uint8_t> in_view;  // per id
  std::vector<std::uint8_t> correct;  // per id: reported within 0.4 square
  std::vector<std::uint8_t> gross;    // per id: reported beyond 0.4 square
  double max_error_sq = 0;            // largest error of any reported marker, in squares
};

struct FrameScore {
  int frame = 0;
  double motion_sq = 0;
  int contact = 0, contact_found = 0, markers = 0, found = 0, gross = 0;
  double max_error_sq = 0;
  double track_ms = 0;  // both views, detection included
};

// Throws std::runtime_error when the rest frame's grid is not identified.
std::vector<FrameScore> playRun(const CampaignRun& run);

ViewScore scoreView(const vision::ViewMarkers& markers, const sim::VirtualCamera& camera, const MarkerField& truth,
                    int width, int height);

}  // namespace onetip::bench
