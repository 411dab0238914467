// viewer/viewer_renderer.hpp — draws one ViewerFrame into the bound
// framebuffer with OpenGL 3.3 core and the shaders in shaders/viewer_*.
//
// Panels (viewer/panel_layout.hpp), each in its own viewport:
//   camera   the grey frame as a texture, letterboxed (area-averaged down
//            to the panel's pixels on the CPU when it is smaller), with the
//            corners as round points (viewer/camera_markers.hpp);
//   field    the deformation surface, lit and coloured by |u| (0 to
//            scale_mm, blue to red), with tangential arrows, seen from above
//            the pad at an angle (S, mm; viewer/field_geometry.hpp), and the
//            colour ramp as a bar;
//   contact  the marker grid from above (S.x right, S.y down as in the left
//            view) with stick/slip colours;
//   pose     the 6-D input object over the pad plane (viewer/input_object.hpp);
//   gauges, timing and every title: the HUD overlay (viewer/hud_painter.hpp),
//            blended over everything, only where it has content
//            (viewer/overlay_regions.hpp).
// Needs a current OpenGL 3.3 core context for its whole life.
#pragma once

#include <memory>
#include <opencv2/core.hpp>

#include "core/calibration.hpp"
#include "viewer/field_geometry.hpp"
#include "viewer/hud_painter.hpp"
#include "viewer/viewer_frame.hpp"

namespace onetip::viewer {

struct ViewerRendererOptions {
  FieldGeometryOptions field;
  double field_scale_mm = 2.0;     // |u| at the red end of the ramp
  double object_gain = 2.0;        // translation magnification of the input object
  float corner_diameter_px = 7.0F;
  std::array<double, 6> working_range{4, 4, 3, 15, 40, 40};
  void validate() const;           // throws InputError naming the bad field
};

class ViewerRenderer {
 public:
  // Compiles the shaders; throws std::runtime_error when they do not build.
  ViewerRenderer(StereoCalibration calibration, ViewerRendererOptions options = {});
  ~ViewerRenderer();
  ViewerRenderer(const ViewerRenderer&) = delete;
  ViewerRenderer& operator=(const ViewerRenderer&) = delete;

  // Draws the frame into the bound framebuffer of `window` pixels.
  void draw(const ViewerFrame& frame, cv::Size window);

 private:
  struct Gl;
  StereoCalibration calibration_;
  ViewerRendererOptions options_;
  std::unique_ptr<Gl> gl_;
};

}  // namespace onetip::viewer
