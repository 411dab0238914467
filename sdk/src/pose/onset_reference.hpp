// pose/onset_reference.hpp — c0, the point whose motion the 6-D signal reports
// (docs/reference.md: "the centroid of the contact region at onset").
//
// The region is the paper's (OneTip, Sec. III-B): the markers whose
// deformation modulus |u_i| (mm) is at least kPaperRegionFraction of the
// largest normal deformation max |u_i.z|, here the 8-connected set of them
// that meets the tracked contact region (another finger's markers stay out).
// c0 is the centroid of their rest positions p_i - u_i (S, mm). The contact
// stage's own region (normal deformation over 40 %, contact_analyzer.hpp)
// follows the true contact more closely and stays what the SDK reports as the
// contact; but a finger moving as it lands drags the skin behind it, the
// modulus region grows there, and the two centroids part by up to half a
// pitch: every later turn theta then moves the reported translation by
// (R(theta) - I)(c0' - c0), 0.1 mm at 20 deg for 0.3 mm. The reference point
// follows the documented definition.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "contact/contact_field.hpp"
#include "core/marker_field.hpp"

namespace onetip::pose {

constexpr double kPaperRegionFraction = 0.5;

// c0 for the contact whose region holds `region_markers` (ids); `fallback`
// (the region's own rest centroid) when no marker passes the paper's cut.
// `now.rows` x `now.cols` is the marker lattice; without one, every marker
// passing the cut counts.
Eigen::Vector3d onsetReferencePoint(const contact::ContactField& field, const MarkerField& now,
                                    const std::vector<int>& region_markers, const Eigen::Vector3d& fallback);

}  // namespace onetip::pose
