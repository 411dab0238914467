// contact/footprint_centre.hpp — where the finger presses, from the normal deformation.
//
// The footprint centre of a contact region is the mean of its markers' current
// positions (S, mm) weighted by how far their normal deformation n_i = -u_i.z
// exceeds the region cut:  c = sum w_i p_i / sum w_i,  w_i = max(0, n_i - cut).
// A marker enters with weight zero, so the centre moves continuously as the
// region grows or travels, whether the skin sticks (the dimple travels with
// the markers) or slides (the dimple travels over them). Falls back to the
// plain mean when no weight is positive. (A paraboloid-apex variant was tried:
// better on a back-and-forth sweep, worse on long slides, so the simpler one stays.)
#pragma once

#include <Eigen/Core>
#include <vector>

namespace onetip::contact {

// positions: current marker positions (S, mm); normal_deformation: n_i (mm), same order.
Eigen::Vector3d footprintCentre(const std::vector<Eigen::Vector3d>& positions,
                                const std::vector<double>& normal_deformation, double cut_mm);

}  // namespace onetip::contact
