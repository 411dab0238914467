// viewer/field_geometry.hpp — the deformation field and the contact map as
// vertex data, from the markers in the sensor frame S (mm).
//
// Displacement u_i = now_i - rest_i where both are valid (zero elsewhere).
// Surface: one vertex per marker at rest_i + exaggeration * u_i (invalid
//   markers at rest_i), normals from the exaggerated grid's central
//   differences, scalar |u_i| (mm); two triangles per grid cell whose four
//   markers are valid.
// Arrows: the tangential part (u.x, u.y) of every marker moved more than
//   min_arrow_mm, drawn from the displaced marker as a line of length
//   arrow_gain * |u_xy| with a two-stroke head (GL_LINES pairs).
// Contact map: one point per marker at its rest (x, y), z = 0 — stick green,
//   slip red, detached orange (labels of pose::PoseStep), in the contact
//   region but unlabelled blue, elsewhere grey; diameter grows with the
//   normal deformation -u.z (from 4 px to 4 + 10 px at 1.5 mm).
#pragma once

#include "contact/contact_field.hpp"
#include "core/marker_field.hpp"
#include "pose/adaptive_pose_estimator.hpp"
#include "viewer/vertex_formats.hpp"

namespace onetip::viewer {

struct FieldGeometryOptions {
  double exaggeration = 2.0;  // displacement scale of the surface
  double arrow_gain = 4.0;    // arrow length per mm of tangential displacement
  double min_arrow_mm = 0.02;
  void validate() const;      // throws InputError naming the bad field
};

// u_i per marker id (zero where now or rest is invalid). Throws InputError
// when the fields are not on the same grid.
std::vector<Eigen::Vector3d> markerDisplacements(const MarkerField& now, const MarkerField& rest);

MeshVertices deformationSurface(const MarkerField& now, const MarkerField& rest, const FieldGeometryOptions& options);
PointVertices displacementArrows(const MarkerField& now, const MarkerField& rest, const FieldGeometryOptions& options);

// Colours of the contact map's classes.
Rgba stickColour();
Rgba slipColour();
PointVertices contactMap(const MarkerField& now, const MarkerField& rest, const contact::ContactField& field,
                         const pose::PoseStep& step);

}  // namespace onetip::viewer
