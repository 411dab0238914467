// viewer/egl_core_context.hpp — a headless desktop OpenGL 3.3 core context
// through EGL, current on the constructing thread for the object's life.
//
// Same approach as sim/raster_gl_context.hpp (Mesa's surfaceless platform, no
// config, no surface: rendering goes to framebuffer objects; llvmpipe without
// a GPU) but with the desktop GL API and a 3.3 core profile, which the viewer's
// GLSL 330 shaders need. The EGL display stays initialised for the process.
#pragma once

#include <string>

namespace onetip::viewer {

class EglCoreContext {
 public:
  // Throws std::runtime_error naming the EGL step that failed.
  EglCoreContext();
  ~EglCoreContext();
  EglCoreContext(const EglCoreContext&) = delete;
  EglCoreContext& operator=(const EglCoreContext&) = delete;

 private:
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
};

// GL_RENDERER and GL_VERSION of the current context, e.g.
// "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6".
std::string currentGlDescription();

}  // namespace onetip::viewer
