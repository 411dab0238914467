#include "sim/glsl_renderer.hpp"

#include <GLES3/gl3.h>

#include <opencv2/core/utility.hpp>
#include <stdexcept>
#include <utility>

#include "sim/glsl_shaders.hpp"
#include "sim/image_effects.hpp"
#include "sim/raster_gl_context.hpp"
#include "sim/raster_view.hpp"

namespace onetip::sim {

namespace {

constexpr float kHousingGrey = 20.0F;  // as the CPU renderer: the housing where no sheet is seen
constexpr float kNothingDrawn = -1.0F; // clear value; no sheet shades below 0
constexpr float kFarMm = 1000.0F;      // depth range of the depth buffer

GLuint compile(GLenum type, const char* source) {
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("GLSL renderer: shader does not compile: ") + log);
  }
  return shader;
}

struct Vertex {
  float x, y, depth, u, v;
};

}  // namespace

struct GlslFrameRenderer::GlState {
  HeadlessGlContext context;
  GLuint program = 0, vao = 0, vbo = 0, ibo = 0, fbo = 0, colour = 0, depth = 0;
  cv::Size frame;

  explicit GlState(cv::Size frame_size) : frame(frame_size) {
    const HeadlessGlContext::Binding bound(context);
    const GLuint vs = compile(GL_VERTEX_SHADER, kCheckerVertexShader);
    const GLuint fs = compile(GL_FRAGMENT_SHADER, kCheckerFragmentShader);
    program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) throw std::runtime_error("GLSL renderer: shader program does not link");

    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glGenBuffers(1, &vbo);
    glGenBuffers(1, &ibo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex), nullptr);
    glVertexAttribPointer(1, 1, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(2 * sizeof(float)));
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(3 * sizeof(float)));
    for (GLuint i = 0; i < 3; ++i) glEnableVertexAttribArray(i);

    glGenRenderbuffers(1, &colour);
    glBindRenderbuffer(GL_RENDERBUFFER, colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_R32F, frame.width, frame.height);
    glGenRenderbuffers(1, &depth);
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, frame.width, frame.height);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("GLSL renderer: no float (R32F) render target");
    GLint read_format = 0, read_type = 0;
    glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_FORMAT, &read_format);
    glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_TYPE, &read_type);
    if (read_format != GL_RED || read_type != GL_FLOAT)
      throw std::runtime_error("GLSL renderer: float single-channel read-back not supported");
  }

  ~GlState() {
    const HeadlessGlContext::Binding bound(context);
    glDeleteFramebuffers(1, &fbo);
    glDeleteRenderbuffers(1, &colour);
    glDeleteRenderbuffers(1, &depth);
    glDeleteBuffers(1, &vbo);
    glDeleteBuffers(1, &ibo);
    glDeleteVertexArrays(1, &vao);
    glDeleteProgram(program);
  }

  void setTexture(const CheckerTexture& t) const {
    glUniform1f(glGetUniformLocation(program, "square_mm"), static_cast<float>(t.square_mm));
    glUniform2f(glGetUniformLocation(program, "board_hi"), static_cast<float>(t.cols * t.square_mm),
                static_cast<float>(t.rows * t.square_mm));
    glUniform1f(glGetUniformLocation(program, "border_mm"), static_cast<float>(t.border_mm));
    glUniform1f(glGetUniformLocation(program, "mid_grey"), static_cast<float>(0.5 * (t.dark + t.light)));
    glUniform1f(glGetUniformLocation(program, "amplitude"), static_cast<float>(0.5 * (t.light - t.dark)));
    glUniform1f(glGetUniformLocation(program, "light_grey"), static_cast<float>(t.light));
    glUniform1f(glGetUniformLocation(program, "background_grey"), static_cast<float>(t.background));
  }

  // Uploads the sheet as seen by `cam` and draws its valid triangles (the
  // same split of each lattice quad as the CPU rasteriser).
  void drawSheet(const CheckerSheet& sheet, const VirtualCamera& cam, double radius2) const {
    const std::vector<ProjectedVertex> projected = projectSheet(sheet, cam, radius2);
    std::vector<Vertex> vertices(projected.size());
    for (size_t i = 0; i < projected.size(); ++i) {
      const size_t a = i % static_cast<size_t>(sheet.nu), b = i / static_cast<size_t>(sheet.nu);
      vertices[i] = {static_cast<float>(projected[i].pixel.x()), static_cast<float>(projected[i].pixel.y()),
                     static_cast<float>(projected[i].depth), static_cast<float>(sheet.u0 + a * sheet.spacing_mm),
                     static_cast<float>(sheet.v0 + b * sheet.spacing_mm)};
    }
    std::vector<GLuint> indices;
    indices.reserve(6 * projected.size());
    const auto add = [&](GLuint i, GLuint j, GLuint k) {
      if (projected[i].valid && projected[j].valid && projected[k].valid) indices.insert(indices.end(), {i, j, k});
    };
    for (int b = 0; b + 1 < sheet.nv; ++b)
      for (int a = 0; a + 1 < sheet.nu; ++a) {
        const auto i00 = static_cast<GLuint>(b * sheet.nu + a), i01 = i00 + static_cast<GLuint>(sheet.nu);
        add(i00, i00 + 1, i01 + 1);
        add(i00, i01 + 1, i01);
      }
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)), vertices.data(),
                 GL_STREAM_DRAW);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(GLuint)), indices.data(),
                 GL_STREAM_DRAW);
    setTexture(sheet.texture);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(indices.size()), GL_UNSIGNED_INT, nullptr);
  }
};

GlslFrameRenderer::GlslFrameRenderer(CameraRig rig)
    : rig_(std::move(rig)), gl_(std::make_unique<GlState>(cv::Size(2 * rig_.view_width, rig_.view_height))) {}

GlslFrameRenderer::~GlslFrameRenderer() = default;

std::string GlslFrameRenderer::glRenderer() const {
  const std::lock_guard lock(mutex_);
  return gl_->context.renderer();
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
    const HeadlessGlContext::Binding bound(gl_->context);
    glBindFramebuffer(GL_FRAMEBUFFER, gl_->fbo);
    glUseProgram(gl_->program);
    glBindVertexArray(gl_->vao);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glViewport(0, 0, 2 * view.width, view.height);
    glClearColor(kNothingDrawn, 0, 0, 1);
    glClearDepthf(1.0F);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUniform2f(glGetUniformLocation(gl_->program, "view_size"), static_cast<float>(view.width),
                static_cast<float>(view.height));
    glUniform1f(glGetUniformLocation(gl_->program, "far_mm"), kFarMm);
    for (int i = 0; i < 2; ++i) {
      glViewport(i * view.width, 0, view.width, view.height);  // window row y = image row y
      const double radius2 = acceptedRadius2(*cameras[i], view);
      for (const CheckerSheet& sheet : sheets) gl_->drawSheet(sheet, *cameras[i], radius2);
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
