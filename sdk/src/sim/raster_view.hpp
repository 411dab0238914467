// sim/raster_view.hpp — CPU rasteriser of a CheckerSheet into one camera view.
//
// Every lattice vertex (S, mm) is mapped to the camera frame by
// camera_from_sensor and projected with VirtualCamera::project (pinhole +
// OpenCV distortion), giving pixel coordinates of the pinhole view (before
// any mirror flip; pixel centres at integers). Each lattice quad is split
// into two triangles, rasterised with exact integer edge functions on a
// 1/256-pixel grid with the top-left fill rule (watertight: no pixel of a
// closed mesh is missed or drawn twice) and a depth test on the camera-frame
// z (mm). Within a triangle (u, v) and z are affine in pixel coordinates; its
// Jacobian gives the pixel footprint for FilteredChecker's box filter.
// Vertices behind the camera or beyond the radius where the distortion
// polynomial stops being monotonic (where projection would fold back) are
// dropped with their triangles.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "sim/camera_rig.hpp"
#include "sim/checker_sheet.hpp"

namespace onetip::sim {

// One view being drawn: pre-effects grey levels and the depth buffer.
struct ViewTarget {
  cv::Mat1f grey;   // grey levels, `empty_grey` where nothing is drawn
  cv::Mat1f depth;  // camera-frame z of the nearest drawn surface, mm; +inf where none
  // Clears to an empty view of `size`, reusing the buffers when they fit.
  void reset(cv::Size size, float empty_grey);
  cv::Mat1b coverage() const;  // 255 where some sheet was drawn
};

// Largest squared normalised image radius (x/z)^2 + (y/z)^2 accepted for
// camera `cam`: where its radial distortion is still monotonic, and at most
// four times the squared radius of the view's corners.
double acceptedRadius2(const VirtualCamera& cam, cv::Size view);

// A sheet vertex seen by a camera: distorted pixel coordinates of the
// pinhole view and camera-frame depth (mm); invalid if dropped (see above).
struct ProjectedVertex {
  Eigen::Vector2d pixel{0, 0};
  double depth = 0;
  bool valid = false;
};
std::vector<ProjectedVertex> projectSheet(const CheckerSheet& sheet, const VirtualCamera& cam,
                                          double accepted_radius2);

// Throws InputError naming the inconsistent field of the sheet's lattice or
// texture (vertex count, sizes, spacing, square size, border).
void validateSheet(const CheckerSheet& sheet);

// Draws `sheet` into `target` as seen by `cam` (validating it first).
void rasterizeSheet(const CheckerSheet& sheet, const VirtualCamera& cam, double accepted_radius2,
                    ViewTarget& target);

}  // namespace onetip::sim
