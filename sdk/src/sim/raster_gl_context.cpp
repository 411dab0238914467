#include "sim/raster_gl_context.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl3.h>

#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace onetip::sim {

namespace {
[[noreturn]] void fail(const char* step) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(eglGetError()));
  throw std::runtime_error(std::string("headless EGL: ") + step + " failed (EGL error " + code + ")");
}
}  // namespace

HeadlessGlContext::HeadlessGlContext() {
  const auto get_platform_display =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!get_platform_display || !client_extensions ||
      !std::strstr(client_extensions, "EGL_MESA_platform_surfaceless"))
    throw std::runtime_error("headless EGL: EGL_MESA_platform_surfaceless is not available");
  EGLDisplay display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY) fail("eglGetPlatformDisplayEXT");
  if (!eglInitialize(display, nullptr, nullptr)) fail("eglInitialize");
  display_ = display;
  if (!eglBindAPI(EGL_OPENGL_ES_API)) fail("eglBindAPI");
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
  EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  if (context == EGL_NO_CONTEXT) fail("eglCreateContext (OpenGL ES 3.0, no config)");
  context_ = context;
}

HeadlessGlContext::~HeadlessGlContext() {
  // The display stays initialised: EGL displays are per process, not
  // reference-counted, so terminating it would break other contexts on it
  // (and Mesa frees its driver state only then, which leak checkers report).
  eglDestroyContext(display_, context_);
}

std::string HeadlessGlContext::renderer() const {
  const Binding bound(*this);
  return reinterpret_cast<const char*>(glGetString(GL_RENDERER));
}

HeadlessGlContext::Binding::Binding(const HeadlessGlContext& context) : context_(context) {
  if (!eglMakeCurrent(context_.display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_.context_)) fail("eglMakeCurrent");
}

HeadlessGlContext::Binding::~Binding() {
  eglMakeCurrent(context_.display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

}  // namespace onetip::sim
