#include "viewer/viewer_renderer.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "gl/gl_program.hpp"
#include "gl/gl_vertex_array.hpp"
#include "viewer/camera_markers.hpp"
#include "viewer/gl_math.hpp"
#include "viewer/gl_texture.hpp"
#include "viewer/input_object.hpp"
#include "viewer/overlay_regions.hpp"
#include "viewer/panel_layout.hpp"
#include "viewer/viewer_shaders.hpp"

namespace onetip::viewer {

using gl::GlProgram;
using gl::GlVertexArray;

namespace {
const Eigen::Vector3f kLight = Eigen::Vector3f(0.3F, -0.5F, 1.0F).normalized();

// Viewport and scissor on a panel (pixels, top-left origin) of the window.
void usePanel(const cv::Rect& r, cv::Size window) {
  glViewport(r.x, window.height - r.y - r.height, r.width, r.height);
  glScissor(r.x, window.height - r.y - r.height, r.width, r.height);
}

float aspectOf(const cv::Rect& r) { return static_cast<float>(r.width) / static_cast<float>(r.height); }

// Half the extent of the rest marker grid in S.x / S.y (mm).
float gridHalfExtent(const MarkerField& rest) {
  double e = 1.0;
  for (int i = 0; i < rest.size(); ++i)
    if (rest.valid[static_cast<size_t>(i)])
      e = std::max({e, std::abs(rest.position[static_cast<size_t>(i)].x()),
                    std::abs(rest.position[static_cast<size_t>(i)].y())});
  return static_cast<float>(e);
}
}  // namespace

void ViewerRendererOptions::validate() const {
  field.validate();
  if (!(field_scale_mm > 0)) throw InputError("viewer: field_scale_mm: must be > 0");
  if (!(object_gain > 0 && object_gain <= 20)) throw InputError("viewer: object_gain: must be in (0, 20]");
  if (!(corner_diameter_px >= 1 && corner_diameter_px <= 64)) throw InputError("viewer: corner_diameter_px: must be in [1, 64]");
  for (double r : working_range)
    if (!(r > 0)) throw InputError("viewer: working_range: every entry must be > 0");
}

struct ViewerRenderer::Gl {
  GlProgram image{"viewer image", kImageVertexShader, kImageFragmentShader};
  GlProgram mesh{"viewer mesh", kMeshVertexShader, kMeshFragmentShader};
  GlProgram points{"viewer points", kPointsVertexShader, kPointsFragmentShader};
  GlVertexArray empty{{}};  // core profile draws need a bound vertex array
  GlVertexArray surface{MeshVertices::layout()}, ramp{MeshVertices::layout()}, box{MeshVertices::layout()};
  GlVertexArray corners{PointVertices::layout()}, arrows{PointVertices::layout()}, contact{PointVertices::layout()};
  GlVertexArray grid{PointVertices::layout()}, axes{PointVertices::layout()};
  GlTexture camera, overlay;
  cv::Mat camera_shown;  // the camera frame averaged down to its panel's pixels
  cv::Mat hud;

  void drawImage(const GlTexture& texture, const Eigen::Vector4f& ndc, bool grey) {
    image.use();
    image.set("u_rect", ndc);
    image.set("u_grey", grey ? 1 : 0);
    image.set("u_image", 0);
    texture.bind(0);
    empty.drawGenerated(GL_TRIANGLE_STRIP, 4);
  }
  void drawMesh(const GlVertexArray& vertices, const Eigen::Matrix4f& view_projection, const Eigen::Matrix4f& model,
                bool by_scalar, float scalar_max, bool lit) {
    mesh.use();
    mesh.set("u_model", model);
    mesh.set("u_view_projection", view_projection);
    mesh.set("u_colour_by_scalar", by_scalar ? 1 : 0);
    mesh.set("u_scalar_max", scalar_max);
    mesh.set("u_light", kLight);
    mesh.set("u_lit", lit ? 1 : 0);
    vertices.draw(GL_TRIANGLES);
  }
  void drawPoints(const GlVertexArray& vertices, const Eigen::Matrix4f& transform, bool as_points) {
    points.use();
    points.set("u_transform", transform);
    points.set("u_points", as_points ? 1 : 0);
    vertices.draw(as_points ? GL_POINTS : GL_LINES);
  }
};

ViewerRenderer::ViewerRenderer(StereoCalibration calibration, ViewerRendererOptions options)
    : calibration_(std::move(calibration)), options_(options) {
  options_.validate();
  gl_ = std::make_unique<Gl>();
  const MeshVertices box = fingerBox({10, 16, 6});
  gl_->box.upload(box.data, box.indices);
  gl_->grid.upload(padGrid(12, 2).data);
  gl_->axes.upload(objectAxes(9).data);
}

ViewerRenderer::~ViewerRenderer() = default;

void ViewerRenderer::draw(const ViewerFrame& frame, cv::Size window) {
  Gl& g = *gl_;
  const PanelLayout layout = PanelLayout::forWindow(window);
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, window.width, window.height);
  glClearColor(0.07F, 0.07F, 0.08F, 1.0F);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glEnable(GL_PROGRAM_POINT_SIZE);
  glDisable(GL_BLEND);
  const Eigen::Matrix4f identity = Eigen::Matrix4f::Identity();

  // Camera frame and corners.
  if (!frame.camera.empty()) {
    const cv::Rect2d fitted = fitInside(frame.camera.size(), layout.camera);
    const cv::Rect viewport(cvRound(fitted.x), cvRound(fitted.y), cvRound(fitted.width), cvRound(fitted.height));
    usePanel(viewport, window);
    // Averaged down on the CPU (area filter: no aliasing, a ninth of the
    // upload and texture reads at 1280x720) when the panel is smaller.
    if (viewport.width < frame.camera.cols && viewport.height < frame.camera.rows) {
      cv::resize(frame.camera, g.camera_shown, viewport.size(), 0, 0, cv::INTER_AREA);
      g.camera.upload(g.camera_shown);
    } else {
      g.camera.upload(frame.camera);
    }
    g.drawImage(g.camera, {-1, -1, 1, 1}, true);
    g.corners.upload(cornerPoints(frame.left, frame.right, calibration_, options_.corner_diameter_px).data);
    g.drawPoints(g.corners, orthographic(0, static_cast<float>(frame.camera.cols), static_cast<float>(frame.camera.rows), 0),
                 true);
  }

  const bool have_field = frame.rest.size() > 0 && frame.result.markers.size() == frame.rest.size();
  const float extent = have_field ? gridHalfExtent(frame.rest) : 10.0F;
  glEnable(GL_DEPTH_TEST);

  // Deformation field, from above the pad at an angle, and the colour ramp.
  usePanel(layout.field, window);
  const float scale = static_cast<float>(options_.field_scale_mm);
  if (have_field) {
    const Eigen::Matrix4f vp = perspective(38.0F, aspectOf(layout.field), 1.0F, 500.0F) *
                               lookAt({0, -2.1F * extent, 2.3F * extent}, {0, 0.1F * extent, -1.0F}, {0, 0, 1});
    const MeshVertices surface = deformationSurface(frame.result.markers, frame.rest, options_.field);
    g.surface.upload(surface.data, surface.indices);
    g.drawMesh(g.surface, vp, identity, true, scale, true);
    g.arrows.upload(displacementArrows(frame.result.markers, frame.rest, options_.field).data);
    g.drawPoints(g.arrows, vp, false);
  }
  MeshVertices ramp;  // panel pixels: a bar along the bottom-left
  const float x0 = 150, x1 = 320, y0 = static_cast<float>(layout.field.height) - 34, y1 = y0 + 12;
  for (float s : {0.0F, 1.0F}) {
    ramp.add({x0 + s * (x1 - x0), y0, 0}, {0, 0, 1}, {1, 1, 1, 1}, s * scale);
    ramp.add({x0 + s * (x1 - x0), y1, 0}, {0, 0, 1}, {1, 1, 1, 1}, s * scale);
  }
  ramp.indices = {0, 2, 3, 0, 3, 1};
  g.ramp.upload(ramp.data, ramp.indices);
  g.drawMesh(g.ramp, orthographic(0, static_cast<float>(layout.field.width), static_cast<float>(layout.field.height), 0),
             identity, true, scale, false);

  // Contact map, top-down, rows growing downwards as in the left view.
  if (have_field) {
    usePanel(layout.contact, window);
    const float half_h = 1.3F * extent, half_w = half_h * aspectOf(layout.contact);
    g.contact.upload(contactMap(frame.result.markers, frame.rest, frame.result.pose.field, frame.result.pose.step).data);
    g.drawPoints(g.contact, orthographic(-half_w, half_w, half_h, -half_h), true);
  }

  // The 6-D input object over the pad plane.
  usePanel(layout.pose, window);
  const Eigen::Matrix4f vp_pose =
      perspective(40.0F, aspectOf(layout.pose), 1.0F, 500.0F) * lookAt({24, -42, 30}, {0, 0, 0}, {0, 0, 1});
  const Eigen::Matrix4f model = inputObjectPose(frame.result.pose.raw, options_.object_gain).matrix().cast<float>();
  g.drawPoints(g.grid, vp_pose, false);
  g.drawMesh(g.box, vp_pose, model, false, 1.0F, true);
  glDisable(GL_DEPTH_TEST);
  g.drawPoints(g.axes, vp_pose * model, false);

  // Text, gauges and timings over everything.
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, window.width, window.height);
  HudSettings hud;
  hud.working_range = options_.working_range;
  hud.field_exaggeration = options_.field.exaggeration;
  hud.field_scale_mm = options_.field_scale_mm;
  hud.object_gain = options_.object_gain;
  paintHud(layout, frame, hud, g.hud);
  const std::vector<cv::Rect> content = overlayRegions(g.hud);  // uploaded and blended only there
  g.overlay.uploadRegions(g.hud, content);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_SCISSOR_TEST);
  for (const cv::Rect& r : content) {
    glScissor(r.x, window.height - r.y - r.height, r.width, r.height);
    g.drawImage(g.overlay, {-1, -1, 1, 1}, false);
  }
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);
}

}  // namespace onetip::viewer
