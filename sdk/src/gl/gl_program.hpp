// gl/gl_program.hpp — an owning wrapper of an OpenGL shader program: a vertex
// + fragment shader pair (GLSL 330 core, from shaders/), compiled and linked,
// with uniforms set by name (Eigen matrices are column-major, as GL expects;
// values are passed through unchanged, in whatever units the shader uses).
//
// Threading: a current 3.3 core context (gl/headless_context.hpp or a GLFW
// window's) is needed for every call, construction and destruction included;
// use the program only in the context that made it.
#pragma once

#include <Eigen/Core>
#include <string>

#include "gl/gl_api.hpp"

namespace onetip::gl {

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
  void set(const char* name, const Eigen::Vector2f& value) const;
  void set(const char* name, const Eigen::Vector3f& value) const;
  void set(const char* name, const Eigen::Vector4f& value) const;
  void set(const char* name, const Eigen::Matrix4f& value) const;

 private:
  GLuint program_ = 0;
};

}  // namespace onetip::gl
