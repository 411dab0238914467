// viewer/hud_painter.hpp — the viewer's text and 2-D gauges, drawn with
// OpenCV into a transparent BGRA overlay (straight alpha) of the window's
// size, which the renderer blends over the GL panels.
//
// Per panel: a frame and a title strip saying what it shows and its key
// numbers. Gauges: one horizontal bar per input axis [dx, dy, dz, yaw,
// pitch, roll], centred on zero and full at the working range (mm, degrees;
// pipeline's PoseTrackerOptions::working_range), red beyond it. Timings: the
// pipeline's stages (ms) with bars on a 0-16.7 ms (60 Hz) scale, the source
// and render times, and the frame rates.
#pragma once

#include <array>
#include <opencv2/core.hpp>

#include "viewer/panel_layout.hpp"
#include "viewer/viewer_frame.hpp"

namespace onetip::viewer {

struct HudSettings {
  std::array<double, 6> working_range{4, 4, 3, 15, 40, 40};
  double field_exaggeration = 2.0;
  double field_scale_mm = 2.0;       // displacement at the top of the colour ramp
  double object_gain = 2.0;
};

// `canvas` is reused between frames (re-allocated when the size changes).
void paintHud(const PanelLayout& layout, const ViewerFrame& frame, const HudSettings& settings, cv::Mat& canvas);

}  // namespace onetip::viewer
