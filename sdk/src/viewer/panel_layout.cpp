#include "viewer/panel_layout.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace onetip::viewer {

PanelLayout PanelLayout::forWindow(cv::Size window) {
  if (window.width < 640 || window.height < 360)
    throw InputError("viewer: window size " + std::to_string(window.width) + "x" + std::to_string(window.height) +
                     " is smaller than 640x360");
  PanelLayout l;
  l.window = window;
  const int half_w = window.width / 2, half_h = window.height / 2;
  l.camera = {0, 0, half_w, half_h};
  l.field = {half_w, 0, window.width - half_w, half_h};
  const int third = window.width / 3, bottom = window.height - half_h;
  l.contact = {0, half_h, third, bottom};
  l.pose = {third, half_h, third, bottom};
  const int column = window.width - 2 * third, gauges_h = bottom / 2;
  l.gauges = {2 * third, half_h, column, gauges_h};
  l.timing = {2 * third, half_h + gauges_h, column, bottom - gauges_h};
  return l;
}

std::array<std::pair<std::string_view, cv::Rect>, 6> PanelLayout::panels() const {
  return {{{"camera", camera}, {"field", field}, {"contact", contact}, {"pose", pose}, {"gauges", gauges},
           {"timing", timing}}};
}

cv::Rect2d fitInside(cv::Size image, const cv::Rect& panel) {
  const double scale = std::min(static_cast<double>(panel.width) / image.width,
                                static_cast<double>(panel.height) / image.height);
  const double w = image.width * scale, h = image.height * scale;
  return {panel.x + 0.5 * (panel.width - w), panel.y + 0.5 * (panel.height - h), w, h};
}

}  // namespace onetip::viewer
