// sim/renderer.hpp — renders what the simulated camera sees: one 8-bit grey
// frame holding both virtual views side by side (docs/reference.md layout).
//
// Each CheckerSheet is a triangle mesh in S textured with an anti-aliased
// checkerboard; it is projected through each VirtualCamera (with distortion),
// rasterised with a depth test, then mirrored into its half if the camera's
// flip is set. ImageEffects are applied last, deterministically from the seed.
// ViewDisturbances (sim/world_effects.hpp) move a view in the image (its
// principal point shifted, sim/camera_shift.hpp) and paint smudges over
// hidden markers (sim/marker_damage.hpp) before the image effects.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "sim/camera_rig.hpp"
#include "sim/checker_sheet.hpp"

namespace onetip::sim {

struct ImageEffects {
  double noise_sigma = 2.0;        // additive Gaussian sensor noise, grey levels
  double blur_sigma = 0.0;         // Gaussian optical blur, pixels (0: none)
  double vignetting = 0.0;         // brightness loss at the view corners, 0..1
  double exposure = 1.0;           // multiplies every grey level (0.2..3)
  double light_gradient = 0.0;     // uneven LED lighting: linear ramp across a view, 0..1
  int dust_blobs = 0;              // dark occluding blobs (dust) per view
  int specular_spots = 0;          // bright saturated spots per view
  double occlusion_fraction = 0.0; // fraction of the pad hidden by a dark band, 0..0.9
  // Where the static effects sit (dust, specular spots, the occluding band, the
  // lighting ramp): fixed for a run so they stay put from frame to frame, as a
  // speck of dust or a shadow would; the per-frame seed drives only the noise.
  std::uint64_t layout_seed = 0;
  void validate() const;           // throws InputError naming the bad field
};

struct ViewDisturbances {
  // Per view (0 left, 1 right): shift of the delivered (mirrored) view, px.
  std::array<Eigen::Vector2d, 2> shift_px{Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
  std::vector<Eigen::Vector3d> smudges;  // centres in S, mm
  double smudge_radius_mm = 0;
  float smudge_grey = 125.0F;            // grey level before exposure
};

class FrameRenderer {
 public:
  explicit FrameRenderer(CameraRig rig);
  // The whole frame: 2 * view_width x view_height, CV_8UC1.
  cv::Mat render(const std::vector<CheckerSheet>& sheets, const ImageEffects& effects, std::uint64_t seed,
                 const ViewDisturbances& disturbances = {}) const;
  const CameraRig& rig() const { return rig_; }

 private:
  CameraRig rig_;
};

}  // namespace onetip::sim
