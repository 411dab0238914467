// sim/glsl_renderer.hpp — FrameRenderer's twin that rasterises with OpenGL ES 3
// shaders (shaders/checker.vert, shaders/checker.frag) in a headless EGL
// context, for comparing the two by speed and accuracy.
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
  // Throws std::runtime_error if no headless EGL / OpenGL ES 3 with float
  // render targets is available, or a shader does not compile.
  explicit GlslFrameRenderer(CameraRig rig);
  ~GlslFrameRenderer();
  // The whole frame: 2 * view_width x view_height, CV_8UC1. Calls are serialised.
  cv::Mat render(const std::vector<CheckerSheet>& sheets, const ImageEffects& effects, std::uint64_t seed) const;
  const CameraRig& rig() const { return rig_; }
  std::string glRenderer() const;  // e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"

 private:
  struct GlState;
  CameraRig rig_;
  std::unique_ptr<GlState> gl_;
  mutable std::mutex mutex_;
};

}  // namespace onetip::sim
