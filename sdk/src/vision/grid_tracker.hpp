// vision/grid_tracker.hpp — marker ids from the checkerboard's rigid links,
// assigned once on the rest frame and tracked frame to frame.
//
// initialize(): the grid graph (vision/grid_graph.hpp) of the detected corners
// gives each corner of the largest consistent grid a lattice (row, col); its
// extent must equal the pattern's. Ids are anchored in the view (after the
// flip): row 0 is the top row, col 0 the leftmost column, col grows with
// image x and row with image y (CONVENTIONS.md), so the left and right views
// of a pair are numbered consistently.
// track(): each id is predicted from its last positions (last position plus
// velocity_gain x its last motion: 0.5 measured best on the simulator's
// scenarios, where full constant velocity overshoots when the motion reverses),
// or, when it was lost, from its tracked grid neighbours (parallelogram and
// midpoint completions); the nearest corner within search_radius x the local
// marker spacing is taken, each corner at most once; a marker whose position
// disagrees with its neighbours' prediction by more than outlier_fraction x
// spacing, or whose links to its neighbours flip direction or change length by
// more than max_link_stretch, is rejected. Markers still lost are recovered
// through the rigid links (vision/grid_recovery.hpp) of the corners detected
// around them, up to recovery_reach x spacing from their prediction.
// Units: view pixels.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/pattern.hpp"
#include "vision/corner_detector.hpp"
#include "vision/view_markers.hpp"

namespace onetip::vision {

struct GridTrackerOptions {
  float search_radius = 0.4f;     // of the local marker spacing
  float outlier_fraction = 0.3f;  // allowed deviation from the neighbour prediction, of spacing
  float max_link_stretch = 2.0f;  // a link may grow or shrink by this factor per frame
  float velocity_gain = 0.5f;     // prediction = last + gain x last motion (0: last position)
  float recovery_reach = 1.0f;    // lost markers recovered through links up to this x spacing away
  void validate() const;          // throws InputError naming the bad field
};

enum class GridStatus {
  Ok,              // markers measured
  NotInitialized,  // track() before a successful initialize()
  GridNotFound,    // no grid of corners could be linked
  GridIncomplete,  // the grid found is smaller than the pattern: ids would be ambiguous
  Lost,            // tracking found too few markers to go on (fewer than 3)
};

struct GridResult {
  GridStatus status = GridStatus::NotInitialized;
  ViewMarkers markers;   // ids -> view pixels
  int found = 0;         // valid markers
  int lost = 0;          // pattern markers not measured this frame
  int rejected = 0;      // matched but rejected as outliers
  int recovered = 0;     // found again after being lost
  std::string message;   // why, when status is not Ok
  double detect_ms = 0;  // time spent detecting corners inside track(view, detector)
  bool ok() const noexcept { return status == GridStatus::Ok; }
};

class GridTracker {
 public:
  explicit GridTracker(MarkerPattern pattern, GridTrackerOptions options = {});

  // Assigns ids on the rest frame: corners in view coordinates of `view`
  // (whose image the grid builder samples to check the links).
  GridResult initialize(const std::vector<Corner>& corners, const ViewHalf& view);
  // The same, detecting the corners first.
  GridResult initialize(const ViewHalf& view, const CornerDetector& detector);
  // The next frame's corners (view coordinates of `view`) -> markers.
  GridResult track(const std::vector<Corner>& corners, const ViewHalf& view);
  // The next frame, searching the image only near the predicted positions
  // (detector.detectNear on the raw half, mapped through the view's flip),
  // and detecting in the region of any lost markers to recover them.
  GridResult track(const ViewHalf& view, const CornerDetector& detector);

  bool initialized() const noexcept { return initialized_; }
  const ViewMarkers& rest() const noexcept { return rest_; }
  const ViewMarkers& current() const noexcept { return current_; }
  const MarkerPattern& pattern() const noexcept { return pattern_; }

 private:
  struct Prediction {
    std::vector<cv::Point2f> point;  // per id, view pixels
    std::vector<float> radius;       // per id, search radius in pixels
  };
  Prediction predict() const;
  void recover(const std::vector<Corner>& corners, const ViewHalf& view, const Prediction& prediction,
               ViewMarkers& candidates) const;
  // Resolves ids claiming the same corner, rejects outliers, updates the state.
  GridResult finish(const Prediction& prediction, ViewMarkers candidates);

  MarkerPattern pattern_;
  GridTrackerOptions options_;
  bool initialized_ = false;
  ViewMarkers rest_;
  ViewMarkers current_;   // last known position of every id (valid: seen in the last frame)
  ViewMarkers previous_;  // the frame before, for the velocity
};

// One-shot: detect + assign ids on a single image of a board (e.g. a
// calibration target with a white border), anchored as above. Throws
// InputError for an empty or non-CV_8UC1 image.
GridResult detectBoard(const cv::Mat& grey, const MarkerPattern& pattern,
                       const CornerDetectorOptions& options = {});
// The same on one view of a frame (ids anchored in the view after its flip).
GridResult detectBoard(const ViewHalf& view, const MarkerPattern& pattern,
                       const CornerDetectorOptions& options = {});

}  // namespace onetip::vision
