// viewer/viewer_frame.hpp — everything one drawn frame shows: the camera
// frame, the pipeline's result for it (markers in S, contact field,
// stick/slip step, 6-D input, stage times), each view's tracked 2-D markers,
// and the viewer's own rates. Units as in pipeline/frame_processor.hpp
// (mm, degrees, milliseconds).
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

#include "core/marker_field.hpp"
#include "pipeline/frame_processor.hpp"
#include "vision/view_markers.hpp"

namespace onetip::viewer {

struct ViewerRates {
  double view_fps = 0;      // drawn frames per second (whole loop), smoothed
  double render_ms = 0;     // drawing this frame (scene building + GL + read-back)
  double source_ms = 0;     // producing the camera frame (decode or simulate + render)
};

struct ViewerFrame {
  std::int64_t index = -1;
  cv::Mat camera;                  // CV_8UC1 whole frame (both views); may be empty
  pipeline::FrameResult result;
  vision::ViewMarkers left, right; // view pixels
  MarkerField rest;                // S (empty before a reference)
  ViewerRates rates;
  std::string source;              // what the frames come from
  std::string hint;                // a help line (e.g. the virtual finger's controls)
};

}  // namespace onetip::viewer
