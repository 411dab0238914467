#include "gl/gl_vertex_array.hpp"

#include <numeric>
#include <stdexcept>

namespace onetip::gl {

GlVertexArray::GlVertexArray(std::vector<int> attribute_sizes)
    : stride_(std::accumulate(attribute_sizes.begin(), attribute_sizes.end(), 0)) {
  glGenVertexArrays(1, &vao_);
  glBindVertexArray(vao_);
  glGenBuffers(1, &vbo_);
  glGenBuffers(1, &ibo_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo_);
  size_t offset = 0;
  for (size_t i = 0; i < attribute_sizes.size(); ++i) {
    glVertexAttribPointer(static_cast<GLuint>(i), attribute_sizes[i], GL_FLOAT, GL_FALSE,
                          static_cast<GLsizei>(stride_ * sizeof(float)), reinterpret_cast<void*>(offset));
    glEnableVertexAttribArray(static_cast<GLuint>(i));
    offset += static_cast<size_t>(attribute_sizes[i]) * sizeof(float);
  }
  glBindVertexArray(0);
}

GlVertexArray::~GlVertexArray() {
  glDeleteBuffers(1, &ibo_);
  glDeleteBuffers(1, &vbo_);
  glDeleteVertexArrays(1, &vao_);
}

void GlVertexArray::upload(const std::vector<float>& vertices, const std::vector<unsigned>& indices) {
  if (stride_ == 0 || vertices.size() % static_cast<size_t>(stride_) != 0)
    throw std::invalid_argument("GlVertexArray::upload: not a whole number of vertices");
  glBindVertexArray(vao_);  // holds the index buffer binding, not the array buffer's
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(float)), vertices.data(),
               GL_DYNAMIC_DRAW);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(unsigned)), indices.data(),
               GL_DYNAMIC_DRAW);
  glBindVertexArray(0);
  vertex_count_ = static_cast<GLsizei>(vertices.size() / static_cast<size_t>(stride_));
  index_count_ = static_cast<GLsizei>(indices.size());
}

void GlVertexArray::draw(GLenum mode) const {
  if (vertex_count_ == 0) return;
  glBindVertexArray(vao_);
  if (index_count_ > 0)
    glDrawElements(mode, index_count_, GL_UNSIGNED_INT, nullptr);
  else
    glDrawArrays(mode, 0, vertex_count_);
  glBindVertexArray(0);
}

void GlVertexArray::drawGenerated(GLenum mode, GLsizei count) const {
  glBindVertexArray(vao_);
  glDrawArrays(mode, 0, count);
  glBindVertexArray(0);
}

}  // namespace onetip::gl
