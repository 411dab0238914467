// tests/unit/pose/sliding_surface.hpp — how far a sliding marker may stray
// from the plane it slides in: the error model of the paper's slip residual
// (Eq. 13-15), as the stick-label oracle (stick_oracle.hpp) gives it to the
// SDK's per-frame problem (pose/weighted_increment.hpp: surface_sd_mm). No SDK
// estimator uses it yet: with the estimators' own labels it did not help
// (decision record 0019).
//
// The sd u of a sliding marker's residual along the normal: its noise s (mm) and the model error of its
// slide. The marker layer is not the finger's surface (it lies d below it, decision record 0003, and bends
// and shears on its own), so a marker that slides by s_t (its motion against the finger over the frame,
// along the tangent plane; S, mm) departs from the plane it slides in by a share f of it, the same relative
// error f as a sticking marker's over its travel (PoseUncertaintyOptions::relative_increment_error):
//   u^2 = s^2 + (f |s_t|)^2.
// Without a slide u = s. Measured under the simulator's true motion (a finger rolled 26 deg sliding at
// 0.1-0.2 mm per frame, 1.5 um noise), the residual's median is 2.3 um at slides under 0.02 mm and 5.4 um
// at 0.1-0.2 mm, with a mean of 2.8 um, the same sign on every sliding marker: with s alone, thirty sliding
// markers outweigh the three that still stick and turn the finger 6 deg in ten frames. (The sagitta of the
// slide over the layer's curvature, kappa |s_t|^2 / 2, is smaller: added to u, it changed no verdict on the
// campaign's odd seeds, so it is left out.)
#pragma once

#include <Eigen/Core>

namespace onetip::poseval {

// u (mm) for noise sd s = noise_sd_mm, the marker's slide against the finger `slide_mm` (S, mm), the unit
// surface normal and f = relative_error in [0, 1].
double slidingSurfaceSd(double noise_sd_mm, const Eigen::Vector3d& slide_mm, const Eigen::Vector3d& normal,
                        double relative_error);

}  // namespace onetip::poseval
