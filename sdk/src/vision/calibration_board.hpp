// vision/calibration_board.hpp — finding a printed checkerboard target in one
// view, for stereo calibration.
//
// OpenCV's classic detector (findChessboardCorners with adaptive threshold and
// image normalisation) on the raw half, then cornerSubPix (half-window
// min(5, 0.4 x the corner spacing) px, no dead zone, 30 iterations / 0.01
// px), the method of the real-photo reference in data/real (README: about
// 0.2 px reprojection on OpenCV's stereo set; wider windows pull corners
// near the board edge). Points are returned in view coordinates (after the
// view's flip) and numbered like markers (docs/reference.md): index =
// row * cols + col with col growing along image x and row along image y, the
// board's symmetries (180 deg; 90 deg and transposes for square boards;
// in-plane mirror images, which for a flat board are 180 deg turns about an
// in-plane axis) resolved in the view, so that the left and right views of a
// pair number the same physical corner alike (alignBoardNumbering below
// makes that hold even for a board turned near 90 deg).
#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "core/pattern.hpp"
#include "vision/view_split.hpp"

namespace onetip::vision {

// rows x cols corners in view pixels, or nothing when the whole board is not
// found. Throws InputError for an empty or non-CV_8UC1 view.
std::optional<std::vector<cv::Point2f>> findCalibrationBoard(const ViewHalf& view,
                                                             const MarkerPattern& pattern);

// Renumbers a rows x cols grid of points (row-major, any of the board's
// symmetric numberings) right-handed, with col as close as possible to image
// x and row to image y.
std::vector<cv::Point2f> anchorBoardNumbering(const std::vector<cv::Point2f>& grid, int rows,
                                              int cols);

// Renumbers `grid` (the other view of the same board) right-handed, with its
// col and row directions as close as possible to those of `reference`. For a
// board turned near 90 deg the image anchor above is a near tie that the two
// views may break differently; this keeps the right view's numbering tied to
// the left's, which is what makes ids stereo correspondences.
std::vector<cv::Point2f> alignBoardNumbering(const std::vector<cv::Point2f>& reference,
                                             const std::vector<cv::Point2f>& grid, int rows,
                                             int cols);

}  // namespace onetip::vision
