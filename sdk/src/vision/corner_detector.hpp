// vision/corner_detector.hpp — checkerboard X-corner detector (the paper's
// double-layer circular sampler, Sec. III-C).
//
// Pipeline on one 8-bit grey image (pixels, centres at integer coordinates):
//  1. pre-filter: a saddle response -det(H) of the image downsampled by
//     prefilter_downsample (Hessian H from Sobel derivatives); its local maxima
//     above a fraction of the strongest are the candidates (no dense ring test);
//  2. quick test of each candidate: its outer ring (scaled by max(1, f/2) for
//     the pre-filter's position error, f = prefilter_downsample) shows four
//     sectors; then sub-pixel refinement (vision/subpixel_refiner.hpp);
//  3. ring test at the refined point (vision/ring_sampler.hpp): two concentric
//     rings of samples must both show four alternating dark/light sectors, be
//     centrally symmetric (any locally affine view of a corner is) and agree in
//     phase; score = contrast x symmetry x phase agreement;
//  4. non-maximum suppression: of corners closer than min_separation_px the
//     best score wins.
// detectNear (tracking) falls back to a fine stage when the default one finds
// nothing, searching within min(search radius, fine_search_px) of the guess:
// rings of fine_inner/outer_radius_px and a refinement window of
// fine_half_window. Where the pad dips steeply at the edge of a deep press a
// square is foreshortened to 6-10 px along one axis, and with blur the
// default 5 px ring and 11 px window take in the next corner's edges, so the
// ring test fails there; the fine stage's rings (1.5 and 2.5 px) and 5 px
// window fit inside a 6 px link and see only the corner itself. (The
// tracker's radius is 0.4 x the shortest predicted link; with 1.2 px of blur
// the default stage also fails at links of 16-17 px, so the fine stage is
// tried after every failure, not only for small radii.)
// Each corner also carries its two edge directions and which sector pair is
// dark (angles in radians, image axes x right, y down, modulo pi), which the
// grid builder uses to link neighbours.
#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "vision/ring_sampler.hpp"
#include "vision/subpixel_refiner.hpp"
#include "vision/view_split.hpp"

namespace onetip::vision {

struct CornerDetectorOptions {
  float inner_radius_px = 3.0f;    // inner sampling ring
  float outer_radius_px = 5.0f;    // outer sampling ring
  int samples_per_ring = 16;       // multiple of 4, 8..64
  int prefilter_downsample = 2;    // 1, 2 or 4
  float prefilter_threshold = 0.01f;  // candidates above this fraction of the max response
  float min_contrast = 6.0f;       // grey levels: mean |sample - ring mean| on both rings
  float min_symmetry = 0.5f;       // 1 - |s(a) - s(a+pi)| / (2 contrast), averaged
  float min_phase_agreement = 0.8f;  // fraction of angles where both rings agree
  float min_separation_px = 4.0f;  // non-maximum suppression distance
  SubpixelOptions subpixel;        // refinement
  float fine_search_px = 6.0f;     // detectNear: the fine stage's search radius, pixels (0: no fine stage)
  float fine_inner_radius_px = 1.5f;  // the fine stage's rings, pixels (fit a 6 px link)
  float fine_outer_radius_px = 2.5f;
  int fine_half_window = 2;        // the fine stage's refinement half window
  void validate() const;           // throws InputError naming the bad field
};

struct Corner {
  cv::Point2f pt;              // pixels, centres at integers
  float score = 0.0f;          // contrast x symmetry x phase agreement (grey levels)
  float contrast = 0.0f;       // grey levels
  float edge_angle[2] = {0, 0};  // the two edge lines through the corner, radians mod pi
  float dark_bisector = 0.0f;  // bisector line of the two dark sectors, radians mod pi
};

class CornerDetector {
 public:
  explicit CornerDetector(CornerDetectorOptions options = {});

  // All corners of a CV_8UC1 image. Throws InputError for an empty image or a
  // wrong type; an image smaller than the rings allow gives no corners.
  std::vector<Corner> detect(const cv::Mat& grey) const;

  // The corner nearest `guess` within search_radius_px, refined and verified
  // by the ring test (the fine stage as a fallback, see above), or nothing.
  // For tracking: no full-image pass.
  std::optional<Corner> detectNear(const cv::Mat& grey, cv::Point2f guess,
                                   float search_radius_px) const;

  // A hint, with no effect on any result: asks the memory system for the
  // pixels detectNear reads around each guess (the refinement window and the
  // rings), all at once. A frame fresh from the camera is not in the cache;
  // fetched marker by marker, every window costs a chain of misses.
  void prefetchNear(const cv::Mat& grey, const std::vector<cv::Point2f>& guesses) const noexcept;

  const CornerDetectorOptions& options() const noexcept { return options_; }

 private:
  // Rings and refinement of one scale.
  struct Stage {
    RingSampler rings;
    RingSampler candidate_rings;  // the quick test of pre-filter candidates
    SubpixelRefiner refiner;
  };
  std::optional<Corner> refineAndVerify(const Stage& stage, const cv::Mat& grey, cv::Point2f start) const;
  std::optional<Corner> searchNear(const Stage& stage, const cv::Mat& grey, cv::Point2f guess, float search_radius_px) const;
  CornerDetectorOptions options_;
  Stage stage_;
  Stage fine_;
};

// A corner seen in the raw half, expressed in view coordinates (position and
// angles mirrored when the view is flipped).
Corner toView(const Corner& raw_corner, const ViewHalf& view);

// Detects on the raw half and returns corners in view coordinates.
std::vector<Corner> detectInView(const CornerDetector& detector, const ViewHalf& view);

}  // namespace onetip::vision
