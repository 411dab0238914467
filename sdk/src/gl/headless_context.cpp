#include "gl/headless_context.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "gl/gl_api.hpp"

namespace onetip::gl {

namespace {
[[noreturn]] void fail(const char* step) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(eglGetError()));
  throw std::runtime_error(std::string("headless OpenGL (EGL): ") + step + " failed (EGL error " + code + ")");
}
}  // namespace

HeadlessContext::HeadlessContext() {
  const auto get_platform_display =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!get_platform_display || !client_extensions || !std::strstr(client_extensions, "EGL_MESA_platform_surfaceless"))
    throw std::runtime_error("headless OpenGL (EGL): EGL_MESA_platform_surfaceless is not available");
  EGLDisplay display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY) fail("eglGetPlatformDisplayEXT");
  if (!eglInitialize(display, nullptr, nullptr)) fail("eglInitialize");
  display_ = display;
  if (!eglBindAPI(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API)");
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  if (context == EGL_NO_CONTEXT) fail("eglCreateContext (OpenGL 3.3 core, no config)");
  context_ = context;
}

HeadlessContext::~HeadlessContext() {
  // The display stays initialised: EGL displays are per process, not
  // reference-counted, so terminating it would break other contexts on it
  // (and Mesa frees its driver state only then, which leak checkers report).
  eglDestroyContext(display_, context_);
}

HeadlessContext::Binding::Binding(const HeadlessContext& context) : context_(context) {
  if (!eglMakeCurrent(context_.display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_.context_)) fail("eglMakeCurrent");
}

HeadlessContext::Binding::~Binding() {
  eglMakeCurrent(context_.display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

std::string currentGlDescription() {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return std::string(renderer ? renderer : "?") + ", " + (version ? version : "?");
}

}  // namespace onetip::gl
