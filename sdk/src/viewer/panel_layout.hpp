// viewer/panel_layout.hpp — where each panel sits in the viewer's window
// (pixels, top-left origin, y down).
//
// Top half: the camera frame (left) and the 3-D deformation field (right).
// Bottom half, in thirds: the contact map with stick/slip labels, the 6-D
// input object, and a column holding the six gauges above the timings.
// fitInside() letterboxes an image into a panel, keeping its aspect ratio.
#pragma once

#include <array>
#include <opencv2/core.hpp>
#include <string_view>

namespace onetip::viewer {

struct PanelLayout {
  cv::Size window;
  cv::Rect camera, field, contact, pose, gauges, timing;

  // Throws InputError when the window is smaller than 640 x 360.
  static PanelLayout forWindow(cv::Size window);
  std::array<std::pair<std::string_view, cv::Rect>, 6> panels() const;
};

cv::Rect2d fitInside(cv::Size image, const cv::Rect& panel);

}  // namespace onetip::viewer
