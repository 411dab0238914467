// vision/grid_tracker.hpp — marker ids from the checkerboard's rigid links,
// assigned once on the rest frame and tracked frame to frame.
//
// initialize(): the grid graph (vision/grid_graph.hpp) of the detected corners
// gives each corner of the largest consistent grid a lattice (row, col); its
// extent must equal the pattern's. Ids are anchored in the view (after the
// flip): row 0 is the top row, col 0 the leftmost column, col grows with
// image x and row with image y (docs/reference.md), so the left and right views
// of a pair are numbered consistently.
// track(): the markers are grown over the grid graph (vision/grid_growth.hpp):
// seeds are the markers that stood still in the last frame, found near their
// last position, and every other marker is searched where its found
// neighbours' motion in this frame puts it (the deformation field is smooth),
// so a reversal or a sudden start of a sliding finger moves the prediction
// with the field; where nothing is found there, once more where its own
// track puts it (a marker sliding past neighbours that stick). With fewer
// than min_seeds seeds (the whole pattern moved, or the last frame was
// lost), the frame is detected whole and relabelled
// through the board's links, anchored to the last ids by the part of the
// pattern that moved least (grid_recovery.hpp). A marker still lost is
// searched where this frame's markers complete it (grid_prediction.hpp; next
// to a stick-slip jump their motion and their places disagree; not within
// half a square of the view's edge), then
// recovered through the rigid links of the corners detected around it, up
// to recovery_reach x spacing from that completion.
// Searches reach search_radius x the shortest predicted link to a
// 4-neighbour (a foreshortened axis cannot bring its neighbour inside);
// "spacing" below is the median link.
// Re-identification without reset: where a link between two reported
// neighbours is more than seam_stretch x both links that continue it along
// its lattice line and a corner sits at its middle (the corner the ids
// skipped), or less than a tenth of both (two ids on one corner), ids slipped
// by a square on one side of it (a region whose markers all agree with each
// other, which no local test sees); the view is then detected whole and every id relabelled from the
// board's links by the majority's lattice offset (grid_recovery.hpp,
// relabelByMajority).
// Swap detector (finish): of two ids on one corner the one its neighbours
// predict better keeps it; a marker is dropped for the frame (never reported
// at a neighbour's position) when it lies more than outlier_fraction x
// spacing from where its neighbours put it (their motion since the last
// frame, grid_growth.hpp, when it was measured then or the frame before,
// else their spatial completion, grid_prediction.hpp), or more than
// spatial_outlier_fraction x spacing from their spatial completion (looser:
// a deep press distorts the lattice by up to half a square, but a run of
// markers shifted together along a line by a whole square keeps its motion,
// not its place), when most
// of its links to its four neighbours flip direction or change length by
// more than max_link_stretch since the last frame, or when two consecutive
// links (right, down, left, up in lattice order) turn the wrong way round
// (links crossing).
// Stick-slip edges: where part of the contact sticks and its neighbours jump,
// a correct marker can lie beyond the tolerance from its neighbours' motion.
// Such a marker (off by motion alone) is taken back where the lattice still
// places it (grid_rescue.hpp): inside the cell of its passing neighbours
// and at most 0.4 of a square (RescueLimits::near_swap_squares) from where
// their motion, their spatial completion or its own track
// (grid_growth.hpp, predictFromOwnTrack) puts it, or within rescue_fraction
// x spacing of every completion by them, or, two neighbours off together,
// inside their pair's cell; confidence at most 0.5.
// Confidence per reported marker, in 0..1 (ViewMarkers::confidence):
//   (1 - residual / (outlier_fraction x spacing)) x (good links / links),
// residual being that distance; 0.5 x the link factor when no neighbour can
// place it.
// A marker lost for one frame keeps its place among its neighbours: its last
// measured position is carried by their motion through that frame
// (predictFromNeighbourMotion) and the next frame searches and checks it
// from there. Under a deep press a correct marker lies up to half a square
// off its neighbours' spatial completion (the lattice's curvature), so that
// completion alone would put it beyond the near-swap bound once its motion
// is lost; only one frame, as each carried frame adds the error of the
// field's motion model (over longer gaps the spatial completion is nearer).
// Units: view pixels.
#pragma once

#include <functional>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/pattern.hpp"
#include "vision/corner_detector.hpp"
#include "vision/view_markers.hpp"

namespace onetip::vision {

struct GridTrackerOptions {
  float search_radius = 0.4f;     // of the shortest predicted link
  float outlier_fraction = 0.3f;  // allowed deviation from where the neighbours' motion puts it, of spacing
  float spatial_outlier_fraction = 0.8f;  // allowed deviation from the neighbours' spatial completion, of spacing
  float max_link_stretch = 2.0f;  // a link may grow or shrink by this factor per frame
  float velocity_gain = 0.5f;     // prediction = last + gain x last motion (0: last position)
  float recovery_reach = 1.0f;    // lost markers recovered through links up to this x spacing away
  float seed_speed = 0.1f;        // of spacing per frame: markers that moved less seed the growth
  float seed_radius = 0.2f;       // of spacing: a seed's search radius
  int min_seeds = 3;              // fewer seeds: detect the whole view and relabel
  float relabel_median = 0.5f;    // of spacing: the relabelling's largest accepted median distance
  float seam_stretch = 1.5f;      // a link this much longer than its collinear neighbours: look for a seam
  float rescue_fraction = 0.15f;   // of spacing: off the neighbours' motion but this close to every completion: kept (0: no rescue at all)
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
  bool relabelled = false;  // a whole-view relabelling (no seeds, or a seam) changed the ids
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
    std::vector<float> radius;       // per id, search radius in pixels (of the shortest link)
    std::vector<float> spacing;      // per id, local spacing (median link) in pixels
    std::vector<cv::Point2f> motion;  // per id, the last frame's motion in pixels (0 where unknown)
    std::vector<std::uint8_t> moving; // per id, motion known (measured in the last two frames)
  };
  // Corners around the given view points, up to `reach` pixels from them
  // (the image path detects in their bounding box; the list path returns all).
  using RegionDetector = std::function<std::vector<Corner>(const std::vector<cv::Point2f>& points, float reach)>;
  Prediction predict() const;
  GridResult trackWith(const std::function<std::optional<cv::Point2f>(cv::Point2f, float)>& near,
                       const RegionDetector& region, const ViewHalf& view);
  // Resolves ids claiming the same corner, rejects outliers, updates the state.
  GridResult finish(const Prediction& prediction, ViewMarkers candidates);
  MarkerPattern pattern_;
  GridTrackerOptions options_;
  bool initialized_ = false;
  ViewMarkers rest_;
  ViewMarkers current_;   // last known position of every id (valid: seen in the last frame)
  ViewMarkers previous_;  // the frame before, for the velocity
  std::vector<std::uint8_t> carried_;  // per id: lost in the last frame, current_ its place carried by its neighbours' motion
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
