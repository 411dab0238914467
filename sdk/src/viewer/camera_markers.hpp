// viewer/camera_markers.hpp — the detected corners drawn over the camera frame.
//
// Markers come per view in view pixels (after that view's flip, vision/
// view_markers.hpp); the camera panel shows the raw frame, so a view point
// (x, y) goes to frame pixel (x_raw + offset, y) with x_raw = w - 1 - x when
// the view is flipped (w its half's width) and offset 0 for the left view,
// split_x for the right one. Colour encodes the id: hue by column (0 to 300
// degrees across the pattern), brightness by row (1 at row 0 down to 0.5);
// the tracking state is the shape: filled disc when measured this frame, ring
// at the last known place when lost (never-seen markers are not drawn).
#pragma once

#include <opencv2/core.hpp>

#include "core/calibration.hpp"
#include "vision/view_markers.hpp"
#include "viewer/vertex_formats.hpp"

namespace onetip::viewer {

Rgba markerIdColour(int id, int rows, int cols);

cv::Point2f framePixel(cv::Point2f view_point, bool right_view, const StereoCalibration& calib);

// Both views' markers in frame pixels (z = 0), `diameter_px` across.
PointVertices cornerPoints(const vision::ViewMarkers& left, const vision::ViewMarkers& right,
                           const StereoCalibration& calib, float diameter_px);

}  // namespace onetip::viewer
