// tests/unit/vision/synthetic_board.hpp — exact synthetic checkerboard images
// for the vision tests and benchmarks (independent of the SDK's detector and
// of the simulator's renderer).
//
// The board: rows x cols inner corners; corner (r, c) sits at pattern
// coordinates (u, v) = (c - (cols-1)/2, r - (rows-1)/2), in squares. Square
// (i, j) = (floor(u), floor(v)) is dark when i + j is even; the board spans
// one square beyond the outer corners, then a light border of one square,
// then background grey.
// The warp maps a view pixel (x, y) (centres at integers) to the pattern:
//   p = (x - cx, y - cy) / square_px,  q = p (1 + bulge exp(-|p|^2 / (2 sigma^2))),
//   (u, v) = Shear(shear) * Rot(-rotation) * q + offset,
// a smooth, invertible radial bulge: local image scale 1 / (1 + bulge) at the
// centre (bulge 0.667: 0.6x; -0.375: 1.6x) and up to ~1.4x on its flank.
// Ground-truth corners are the exact inverse images of the pattern corners
// (Newton's method). Pixels are box-filtered over 4x4 sub-samples near edges
// (exact elsewhere), then optional Gaussian blur, a linear lighting ramp
// (multiplicative, across x), an occluding dark band, additive Gaussian noise
// from a fixed seed, rounded to 8 bits.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

namespace onetip::vision::testing {

struct BoardWarp {
  double cx = 480, cy = 540;   // pixel mapped to the pattern origin
  double square_px = 40;       // rest square size in pixels
  double bulge = 0;            // see above
  double bulge_sigma = 3;      // squares
  double rotation_deg = 0;
  double shear = 0;
  cv::Point2d offset{0, 0};    // squares

  cv::Point2d toPattern(cv::Point2d pixel) const;
  cv::Point2d toPixel(cv::Point2d pattern) const;  // Newton's method on toPattern
};

struct BoardLook {
  int rows = 17, cols = 17;
  double dark = 40, light = 210, background = 90;
  double blur_sigma = 0.0;
  double noise_sigma = 0.0;
  double light_ramp = 0.0;            // brightness x (1 - ramp/2 + ramp x/width)
  cv::Rect2d occluder{0, 0, 0, 0};    // in pattern squares: hidden behind a dark band
  std::uint64_t seed = 1;
};

// Renders width x height, CV_8UC1.
cv::Mat renderBoard(const BoardWarp& warp, const BoardLook& look, cv::Size size);

struct GroundTruthCorner {
  int row, col;
  cv::Point2d pixel;
  bool visible;  // inside the image by a margin and not occluded
};
std::vector<GroundTruthCorner> groundTruthCorners(const BoardWarp& warp, const BoardLook& look, cv::Size size,
                                                  double margin_px = 12);

}  // namespace onetip::vision::testing
