#include "sim/glsl_renderer.hpp"

#include <opencv2/core/utility.hpp>
#include <utility>

#include "gl/gl_api.hpp"
#include "gl/gl_program.hpp"
#include "gl/gl_vertex_array.hpp"
#include "gl/headless_context.hpp"
#include "gl/offscreen_target.hpp"
#include "sim/glsl_shaders.hpp"
#include "sim/image_effects.hpp"
#include "sim/raster_view.hpp"

namespace onetip::sim {

namespace {

constexpr float kHousingGrey = 20.0F;  // as the CPU renderer: the housing where no sheet is seen
constexpr float kNothingDrawn = -1.0F; // clear value; no sheet shades below 0
constexpr float kFarMm = 1000.0F;      // depth range of the depth buffer

// The GL objects of the renderer; made and deleted with its context current.
struct GlObjects {
  gl::GlProgram program{"GLSL renderer", kCheckerVertexShader, kCheckerFragmentShader};
  gl::GlVertexArray lattice{{2, 1, 2}};  // shaders/checker.vert's pixel, depth, uv
  gl::OffscreenTarget target;            // float grey levels, both views side by side

  explicit GlObjects(cv::Size frame) : target(frame, GL_R32F) {}

  void setTexture(const CheckerTexture& t) const {
    program.set("square_mm", static_cast<float>(t.square_mm));
    program.set("board_hi",
                Eigen::Vector2f(static_cast<float>(t.cols * t.square_mm), static_cast<float>(t.rows * t.square_mm)));
    program.set("border_mm", static_cast<float>(t.border_mm));
    program.set("mid_grey", static_cast<float>(0.5 * (t.dark + t.light)));
    program.set("amplitude", static_cast<float>(0.5 * (t.light - t.dark)));
    program.set("light_grey", static_cast<float>(t.light));
    program.set("background_grey", static_cast<float>(t.background));
  }

  // Uploads the sheet as seen by `cam` and draws its valid triangles (the
  // same split of each lattice quad as the CPU rasteriser).
  void drawSheet(const CheckerSheet& sheet, const VirtualCamera& cam, double radius2) {
    const std::vector<ProjectedVertex> projected = projectSheet(sheet, cam, radius2);
    std::vector<float> vertices;
    vertices.reserve(static_cast<size_t>(lattice.floatsPerVertex()) * projected.size());
    for (size_t i = 0; i < projected.size(); ++i) {
      const size_t a = i % static_cast<size_t>(sheet.nu), b = i / static_cast<size_t>(sheet.nu);
      vertices.insert(vertices.end(),
                      {static_cast<float>(projected[i].pixel.x()), static_cast<float>(projected[i].pixel.y()),
                       static_cast<float>(projected[i].depth), static_cast<float>(sheet.u0 + a * sheet.spacing_mm),
                       static_cast<float>(sheet.v0 + b * sheet.spacing_mm)});
    }
    std::vector<unsigned> indices;
    indices.reserve(6 * projected.size());
    const auto add = [&](unsigned i, unsigned j, unsigned k) {
      if (projected[i].valid && projected[j].valid && projected[k].valid) indices.insert(indices.end(), {i, j, k});
    };
    for (int b = 0; b + 1 < sheet.nv; ++b)
      for (int a = 0; a + 1 < sheet.nu; ++a) {
        const auto i00 = static_cast<unsigned>(b * sheet.nu + a), i01 = i00 + static_cast<unsigned>(sheet.nu);
        add(i00, i00 + 1, i01 + 1);
        add(i00, i01 + 1, i01);
      }
    if (indices.empty()) return;  // no triangle in view (unindexed, draw() would take every vertex)
    lattice.upload(vertices, indices);
    setTexture(sheet.texture);
    lattice.draw(GL_TRIANGLES);
  }
};

}  // namespace

struct GlslFrameRenderer::GlState {
  gl::HeadlessContext context;
  std::unique_ptr<GlObjects> objects;

  explicit GlState(cv::Size frame) {
    const gl::HeadlessContext::Binding bound(context);
    objects = std::make_unique<GlObjects>(frame);
  }

  ~GlState() {
    const gl::HeadlessContext::Binding bound(context);
    objects.reset();
  }
};

GlslFrameRenderer::GlslFrameRenderer(CameraRig rig)
    : rig_(std::move(rig)), gl_(std::make_unique<GlState>(cv::Size(2 * rig_.view_width, rig_.view_height))) {}

GlslFrameRenderer::~GlslFrameRenderer() = default;

std::string GlslFrameRenderer::glRenderer() const {
  const std::lock_guard lock(mutex_);
  const gl::HeadlessContext::Binding bound(gl_->context);
  return gl::currentGlDescription();
}

cv::Mat GlslFrameRenderer::render(const std::vector<CheckerSheet>& sheets, const ImageEffects& effects,
                                  std::uint64_t seed) const {
  effects.validate();
  for (const CheckerSheet& sheet : sheets) validateSheet(sheet);
  const cv::Size view(rig_.view_width, rig_.view_height);
  const VirtualCamera* cameras[2] = {&rig_.left, &rig_.right};
  cv::Mat1f grey(view.height, 2 * view.width);
  {
    const std::lock_guard lock(mutex_);
    const gl::HeadlessContext::Binding bound(gl_->context);
    GlObjects& g = *gl_->objects;
    g.target.bind();
    g.program.use();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glViewport(0, 0, 2 * view.width, view.height);
    glClearColor(kNothingDrawn, 0, 0, 1);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    g.program.set("view_size", Eigen::Vector2f(static_cast<float>(view.width), static_cast<float>(view.height)));
    g.program.set("far_mm", kFarMm);
    for (int i = 0; i < 2; ++i) {
      glViewport(i * view.width, 0, view.width, view.height);  // window row y = image row y
      const double radius2 = acceptedRadius2(*cameras[i], view);
      for (const CheckerSheet& sheet : sheets) g.drawSheet(sheet, *cameras[i], radius2);
    }
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, grey.cols, grey.rows, GL_RED, GL_FLOAT, grey.data);
  }
  cv::Mat frame(view.height, 2 * view.width, CV_8UC1);
  cv::parallel_for_(cv::Range(0, 2), [&](const cv::Range& range) {
    for (int i = range.start; i < range.end; ++i) {
      cv::Mat1f half = grey(cv::Rect(i * view.width, 0, view.width, view.height));
      cv::Mat1b pad;
      cv::compare(half, 0.0, pad, cv::CMP_GE);
      half.setTo(kHousingGrey, ~pad);
      developView(
          half, [&] { return pad; }, effects, seed, i, cameras[i]->flip,
          frame(cv::Rect(i * view.width, 0, view.width, view.height)));
    }
  });
  return frame;
}

}  // namespace onetip::sim
