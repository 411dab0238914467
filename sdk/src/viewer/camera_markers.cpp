#include "viewer/camera_markers.hpp"

#include <algorithm>
#include <cmath>

namespace onetip::viewer {

namespace {
// HSV (hue in degrees, saturation and value in [0, 1]) to RGB.
Rgba hsv(double hue_deg, double s, double v) {
  const double h = std::fmod(hue_deg, 360.0) / 60.0;
  const double c = v * s, x = c * (1 - std::abs(std::fmod(h, 2.0) - 1)), m = v - c;
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(h)) {
    case 0: r = c, g = x; break;
    case 1: r = x, g = c; break;
    case 2: g = c, b = x; break;
    case 3: g = x, b = c; break;
    case 4: r = x, b = c; break;
    default: r = c, b = x; break;
  }
  return {static_cast<float>(r + m), static_cast<float>(g + m), static_cast<float>(b + m), 1.0F};
}
}  // namespace

Rgba markerIdColour(int id, int rows, int cols) {
  const int row = id / cols, col = id % cols;
  const double along_cols = cols > 1 ? static_cast<double>(col) / (cols - 1) : 0.0;
  const double along_rows = rows > 1 ? static_cast<double>(row) / (rows - 1) : 0.0;
  return hsv(300.0 * along_cols, 1.0, 1.0 - 0.5 * along_rows);
}

cv::Point2f framePixel(cv::Point2f view_point, bool right_view, const StereoCalibration& calib) {
  const bool flipped = right_view ? calib.flip_right : calib.flip_left;
  const int width = right_view ? calib.rightWidth() : calib.leftWidth();
  const float x_raw = flipped ? static_cast<float>(width - 1) - view_point.x : view_point.x;
  return {x_raw + static_cast<float>(right_view ? calib.split_x : 0), view_point.y};
}

PointVertices cornerPoints(const vision::ViewMarkers& left, const vision::ViewMarkers& right,
                           const StereoCalibration& calib, float diameter_px) {
  PointVertices points;
  const Rgba lost(1.0F, 0.2F, 0.2F, 1.0F);
  for (const bool is_right : {false, true}) {
    const vision::ViewMarkers& view = is_right ? right : left;
    for (int id = 0; id < view.size(); ++id) {
      const auto i = static_cast<size_t>(id);
      const bool measured = view.valid[i] != 0;
      if (!measured && view.point[i] == cv::Point2f(0, 0)) continue;  // never seen
      const cv::Point2f p = framePixel(view.point[i], is_right, calib);
      points.add({p.x, p.y, 0.0F}, measured ? markerIdColour(id, view.rows, view.cols) : lost, diameter_px, !measured);
    }
  }
  return points;
}

}  // namespace onetip::viewer
