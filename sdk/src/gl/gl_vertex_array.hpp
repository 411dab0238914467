// gl/gl_vertex_array.hpp — an owning wrapper of an OpenGL vertex array: one
// interleaved float vertex buffer whose attribute i (location i) has sizes[i]
// floats, with an optional index buffer (unsigned 32-bit indices); re-uploaded
// whenever its contents change (GL_DYNAMIC_DRAW). Sizes and counts are in
// floats and vertices, not bytes.
//
// Threading: a current 3.3 core context (gl/headless_context.hpp or a GLFW
// window's) is needed for every call, construction and destruction included;
// use the array only in the context that made it.
#pragma once

#include <vector>

#include "gl/gl_api.hpp"

namespace onetip::gl {

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
  // Draws what was uploaded (nothing when empty) as `mode` (GL_TRIANGLES, ...):
  // the indexed primitives if indices were uploaded, else all the vertices in order.
  void draw(GLenum mode) const;
  // Draws `count` vertices that the vertex shader makes from gl_VertexID
  // alone (no attributes read; a vertex array must still be bound).
  void drawGenerated(GLenum mode, GLsizei count) const;

 private:
  GLuint vao_ = 0, vbo_ = 0, ibo_ = 0;
  int stride_ = 0;
  GLsizei vertex_count_ = 0, index_count_ = 0;
};

}  // namespace onetip::gl
