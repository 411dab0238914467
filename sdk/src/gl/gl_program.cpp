#include "gl/gl_program.hpp"

#include <optional>
#include <stdexcept>

namespace onetip::gl {

namespace {
// Nothing if a shader's or program's `status` (GL_COMPILE_STATUS,
// GL_LINK_STATUS) is set, else its info log.
template <typename GetParameter, typename GetInfoLog>
std::optional<std::string> failureLog(GLuint object, GetParameter get_parameter, GLenum status,
                                      GetInfoLog get_info_log) {
  GLint ok = 0;
  get_parameter(object, status, &ok);
  if (ok) return std::nullopt;
  char log[2048] = {};
  get_info_log(object, sizeof log, nullptr, log);
  return log;
}

GLuint compileShader(const std::string& name, GLenum type, const char* source) {
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  if (const auto log = failureLog(shader, glGetShaderiv, GL_COMPILE_STATUS, glGetShaderInfoLog)) {
    glDeleteShader(shader);
    throw std::runtime_error(name + (type == GL_VERTEX_SHADER ? ": vertex" : ": fragment") +
                             " shader does not compile: " + *log);
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
  if (const auto log = failureLog(program_, glGetProgramiv, GL_LINK_STATUS, glGetProgramInfoLog)) {
    glDeleteProgram(program_);
    throw std::runtime_error(name + ": shader program does not link: " + *log);
  }
}

GlProgram::~GlProgram() { glDeleteProgram(program_); }
void GlProgram::use() const { glUseProgram(program_); }
void GlProgram::set(const char* name, int value) const { glUniform1i(glGetUniformLocation(program_, name), value); }
void GlProgram::set(const char* name, float value) const { glUniform1f(glGetUniformLocation(program_, name), value); }
void GlProgram::set(const char* name, const Eigen::Vector2f& v) const {
  glUniform2f(glGetUniformLocation(program_, name), v.x(), v.y());
}
void GlProgram::set(const char* name, const Eigen::Vector3f& v) const {
  glUniform3f(glGetUniformLocation(program_, name), v.x(), v.y(), v.z());
}
void GlProgram::set(const char* name, const Eigen::Vector4f& v) const {
  glUniform4f(glGetUniformLocation(program_, name), v.x(), v.y(), v.z(), v.w());
}
void GlProgram::set(const char* name, const Eigen::Matrix4f& m) const {
  glUniformMatrix4fv(glGetUniformLocation(program_, name), 1, GL_FALSE, m.data());
}

}  // namespace onetip::gl
