// sim/glsl_renderer.hpp — FrameRenderer's twin that rasterises with OpenGL 3.3
// core shaders (shaders/checker.vert, shaders/checker.frag) in a headless EGL
// context (gl/headless_context.hpp), for comparing the two by speed and accuracy.
//
// Same scene, same output: sheet vertices are projected on the CPU exactly
// as in raster_view.hpp (VirtualCamera::project, distortion included), the
// GPU (or Mesa's llvmpipe) rasterises the lattice triangles with a depth
// test into one float frame, both views side by side, the fragment shader
// box-filters the checkerboard as FilteredChecker does; then the frame is read
// back and each view developed on the CPU with the same image effects
// (image_effects.hpp). Differences from the CPU path: single-precision
// shading and the GL rasteriser's own sub-pixel snapping.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "sim/renderer.hpp"

namespace onetip::sim {

class GlslFrameRenderer {
 public:
  // Throws std::runtime_error if no headless EGL / OpenGL 3.3 core context with
  // float (R32F) render targets is available, or a shader does not compile.
  explicit GlslFrameRenderer(CameraRig rig);
  ~GlslFrameRenderer();
  // The whole frame: 2 * view_width x view_height, CV_8UC1. Calls may come from
  // any thread; they are serialised (the GL context is current only inside one).
  cv::Mat render(const std::vector<CheckerSheet>& sheets, const ImageEffects& effects, std::uint64_t seed) const;
  const CameraRig& rig() const { return rig_; }
  // GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6".
  std::string glRenderer() const;

 private:
  struct GlState;
  CameraRig rig_;
  std::unique_ptr<GlState> gl_;
  mutable std::mutex mutex_;
};

}  // namespace onetip::sim
