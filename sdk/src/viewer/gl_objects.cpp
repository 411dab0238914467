#include "viewer/gl_objects.hpp"

#include <numeric>
#include <stdexcept>

namespace onetip::viewer {

namespace {
GLuint compileShader(const std::string& name, GLenum type, const char* source) {
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    glDeleteShader(shader);
    throw std::runtime_error(name + (type == GL_VERTEX_SHADER ? ": vertex" : ": fragment") +
                             " shader does not compile: " + log);
  }
  return shader;
}
}  // namespace

GlProgram::GlProgram(const std::string& name, const char* vertex_source, const char* fragment_source) {
  const GLuint vs = compileShader(name, GL_VERTEX_SHADER, vertex_source);
  GLuint fs = 0;
  try {
    fs = compileShader(name, GL_FRAGMENT_SHADER, fragment_source);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  program_ = glCreateProgram();
  glAttachShader(program_, vs);
  glAttachShader(program_, fs);
  glLinkProgram(program_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetProgramInfoLog(program_, sizeof log, nullptr, log);
    glDeleteProgram(program_);
    throw std::runtime_error(name + ": shader program does not link: " + log);
  }
}

GlProgram::~GlProgram() { glDeleteProgram(program_); }
void GlProgram::use() const { glUseProgram(program_); }
void GlProgram::set(const char* name, int value) const { glUniform1i(glGetUniformLocation(program_, name), value); }
void GlProgram::set(const char* name, float value) const { glUniform1f(glGetUniformLocation(program_, name), value); }
void GlProgram::set(const char* name, const Eigen::Vector3f& v) const {
  glUniform3f(glGetUniformLocation(program_, name), v.x(), v.y(), v.z());
}
void GlProgram::set(const char* name, const Eigen::Vector4f& v) const {
  glUniform4f(glGetUniformLocation(program_, name), v.x(), v.y(), v.z(), v.w());
}
void GlProgram::set(const char* name, const Eigen::Matrix4f& m) const {
  glUniformMatrix4fv(glGetUniformLocation(program_, name), 1, GL_FALSE, m.data());
}

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

GlTexture::GlTexture() {
  glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

GlTexture::~GlTexture() { glDeleteTextures(1, &texture_); }

namespace {
void checkUploadable(const cv::Mat& image) {
  if (image.empty() || (image.type() != CV_8UC1 && image.type() != CV_8UC4))
    throw std::invalid_argument("GlTexture::upload: expected a non-empty CV_8UC1 or CV_8UC4 image");
}
GLenum pixelFormat(const cv::Mat& image) { return image.type() == CV_8UC1 ? GL_RED : GL_BGRA; }
}  // namespace

void GlTexture::upload(const cv::Mat& image) {
  checkUploadable(image);
  const cv::Mat pixels = image.isContinuous() ? image : image.clone();
  const bool grey = pixels.type() == CV_8UC1;
  glBindTexture(GL_TEXTURE_2D, texture_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const GLenum format = pixelFormat(pixels);
  if (pixels.size() != size_ || pixels.type() != type_) {
    glTexImage2D(GL_TEXTURE_2D, 0, grey ? GL_R8 : GL_RGBA8, pixels.cols, pixels.rows, 0, format, GL_UNSIGNED_BYTE,
                 pixels.data);
    size_ = pixels.size();
    type_ = pixels.type();
  } else {
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, pixels.cols, pixels.rows, format, GL_UNSIGNED_BYTE, pixels.data);
  }
}

void GlTexture::uploadRegions(const cv::Mat& image, const std::vector<cv::Rect>& regions) {
  checkUploadable(image);
  if (image.size() != size_ || image.type() != type_) {
    upload(image);
    return;
  }
  const cv::Rect whole({0, 0}, image.size());
  glBindTexture(GL_TEXTURE_2D, texture_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, static_cast<GLint>(image.step1() / static_cast<size_t>(image.channels())));
  for (const cv::Rect& r : regions) {
    if ((r & whole) != r) {
      glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
      throw std::invalid_argument("GlTexture::uploadRegions: a region lies outside the image");
    }
    glTexSubImage2D(GL_TEXTURE_2D, 0, r.x, r.y, r.width, r.height, pixelFormat(image), GL_UNSIGNED_BYTE,
                    image.ptr(r.y, r.x));
  }
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
}

void GlTexture::bind(int unit) const {
  glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
  glBindTexture(GL_TEXTURE_2D, texture_);
}

}  // namespace onetip::viewer
