// gl/headless_context.hpp — a headless desktop OpenGL 3.3 core context through
// EGL (Mesa's surfaceless platform: no window, no display server, no config,
// no surface; llvmpipe on machines without a GPU). Rendering goes to
// framebuffer objects (gl/offscreen_target.hpp). A 3.3 core profile, which
// the GLSL 330 shaders in shaders/ need.
//
// Threading: the EGL display is initialised once and left so for the process
// (displays are shared, not reference-counted); each object owns one context.
// A context is current on at most one thread at a time, and only while a
// Binding is alive: it makes the context current on the calling thread on
// construction and releases it on destruction. Hold one for the object's life
// to keep the context current on the constructing thread (the viewer), or one
// around each block of GL calls to use the context from different threads, one
// at a time (the simulator's GLSL renderer). GL objects made in the context
// must be deleted while it is current, before the context itself.
#pragma once

#include <string>

namespace onetip::gl {

class HeadlessContext {
 public:
  // Throws std::runtime_error naming the EGL step that failed.
  HeadlessContext();
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  class Binding {
   public:
    // Throws std::runtime_error if the context cannot be made current (for
    // example while it is current on another thread).
    explicit Binding(const HeadlessContext& context);
    ~Binding();
    Binding(const Binding&) = delete;
    Binding& operator=(const Binding&) = delete;

   private:
    const HeadlessContext& context_;
  };

 private:
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
};

// GL_RENDERER and GL_VERSION of the context current on the calling thread, e.g.
// "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6".
std::string currentGlDescription();

}  // namespace onetip::gl
