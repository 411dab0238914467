// viewer/gl_objects.hpp — owning wrappers of the OpenGL objects the viewer
// uses (a current 3.3 core context is needed for every call, construction and
// destruction included).
//
// GlProgram: a vertex + fragment shader pair (GLSL 330 core, shaders/viewer_*),
// compiled and linked; uniforms set by name (Eigen matrices are column-major,
// as GL expects). GlVertexArray: one interleaved float vertex buffer whose
// attribute i (location i) has sizes[i] floats, with an optional index
// buffer; re-uploaded whenever its contents change (GL_DYNAMIC_DRAW).
// GlTexture: an image texture, linear filtering, clamped edges; CV_8UC1
// images become one-channel (R8) textures, CV_8UC4 (BGRA, OpenCV order) RGBA.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "viewer/gl_api.hpp"

namespace onetip::viewer {

class GlProgram {
 public:
  // Throws std::runtime_error with the compiler's log when a shader does not
  // compile or the program does not link; `name` prefixes the message.
  GlProgram(const std::string& name, const char* vertex_source, const char* fragment_source);
  ~GlProgram();
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;

  void use() const;
  // Uniform setters (use() first); names the shader does not use are ignored.
  void set(const char* name, int value) const;
  void set(const char* name, float value) const;
  void set(const char* name, const Eigen::Vector3f& value) const;
  void set(const char* name, const Eigen::Vector4f& value) const;
  void set(const char* name, const Eigen::Matrix4f& value) const;

 private:
  GLuint program_ = 0;
};

class GlVertexArray {
 public:
  explicit GlVertexArray(std::vector<int> attribute_sizes);
  ~GlVertexArray();
  GlVertexArray(const GlVertexArray&) = delete;
  GlVertexArray& operator=(const GlVertexArray&) = delete;

  int floatsPerVertex() const noexcept { return stride_; }
  // Interleaved vertices (a multiple of floatsPerVertex() floats) and, for
  // indexed drawing, triangle or line indices.
  void upload(const std::vector<float>& vertices, const std::vector<unsigned>& indices = {});
  // Draws what was uploaded (nothing when empty) as `mode` (GL_TRIANGLES, ...).
  void draw(GLenum mode) const;
  // Draws `count` vertices that the vertex shader makes from gl_VertexID
  // alone (no attributes read; a vertex array must still be bound).
  void drawGenerated(GLenum mode, GLsizei count) const;

 private:
  GLuint vao_ = 0, vbo_ = 0, ibo_ = 0;
  int stride_ = 0;
  GLsizei vertex_count_ = 0, index_count_ = 0;
};

class GlTexture {
 public:
  GlTexture();
  ~GlTexture();
  GlTexture(const GlTexture&) = delete;
  GlTexture& operator=(const GlTexture&) = delete;

  // Throws std::invalid_argument for an empty image or a type other than
  // CV_8UC1 / CV_8UC4.
  void upload(const cv::Mat& image);
  // Updates only `regions` (pixels, inside the image) from `image`, or all of
  // it when its size or type differs from the texture's; texels outside the
  // regions keep what they held.
  void uploadRegions(const cv::Mat& image, const std::vector<cv::Rect>& regions);
  void bind(int unit) const;
  bool empty() const noexcept { return size_.area() == 0; }

 private:
  GLuint texture_ = 0;
  cv::Size size_;
  int type_ = -1;
};

}  // namespace onetip::viewer
