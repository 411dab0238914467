// sim/raster_gl_context.hpp — a headless OpenGL ES 3 context through EGL
// (Mesa's surfaceless platform: no window, no display server; llvmpipe on
// machines without a GPU). Rendering goes to framebuffer objects.
//
// The EGL display is initialised once and left so for the process (displays
// are shared, not reference-counted); each object owns one context.
// The context is current on at most one thread at a time: use a Binding
// (makes it current on construction, releases it on destruction) around
// every block of GL calls.
#pragma once

#include <string>

namespace onetip::sim {

class HeadlessGlContext {
 public:
  // Throws std::runtime_error saying which EGL step failed.
  HeadlessGlContext();
  ~HeadlessGlContext();
  HeadlessGlContext(const HeadlessGlContext&) = delete;
  HeadlessGlContext& operator=(const HeadlessGlContext&) = delete;

  std::string renderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"

  class Binding {
   public:
    explicit Binding(const HeadlessGlContext& context);
    ~Binding();
    Binding(const Binding&) = delete;
    Binding& operator=(const Binding&) = delete;

   private:
    const HeadlessGlContext& context_;
  };

 private:
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
};

}  // namespace onetip::sim
