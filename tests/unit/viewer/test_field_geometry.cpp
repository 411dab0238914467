// The deformation surface, arrows, contact map and corner points against
// fields with known displacements.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "viewer/camera_markers.hpp"
#include "viewer/field_geometry.hpp"

namespace onetip::viewer {
namespace {

// A flat rest grid (spacing 1.2 mm, centred) and a Gaussian dent pushed into it.
struct Fields {
  MarkerField rest{5, 6}, now{5, 6};
  Fields() {
    for (int id = 0; id < rest.size(); ++id) {
      const Eigen::Vector3d p((id % 6 - 2.5) * 1.2, (id / 6 - 2.0) * 1.2, 0.0);
      rest.set(id, p);
      const double dent = -1.0 * std::exp(-p.squaredNorm() / 4.0);
      now.set(id, p + Eigen::Vector3d(0.05 * p.x(), 0.0, dent));
    }
  }
};

TEST(FieldGeometry, DisplacementsAreNowMinusRestAndZeroWhereInvalid) {
  Fields f;
  f.now.valid[7] = 0;
  const auto u = markerDisplacements(f.now, f.rest);
  ASSERT_EQ(u.size(), 30U);
  for (size_t i = 0; i < u.size(); ++i) {
    const Eigen::Vector3d expected = i == 7 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(f.now.position[i] - f.rest.position[i]);
    EXPECT_NEAR((u[i] - expected).norm(), 0.0, 1e-12) << i;
  }
  EXPECT_THROW(markerDisplacements(MarkerField(4, 6), f.rest), InputError);
}

TEST(FieldGeometry, SurfaceVerticesAreExaggeratedDisplacementsColouredByModulus) {
  Fields f;
  FieldGeometryOptions o;
  o.exaggeration = 3.0;
  const MeshVertices mesh = deformationSurface(f.now, f.rest, o);
  ASSERT_EQ(mesh.count(), 30);
  for (int i = 0; i < 30; ++i) {
    const Eigen::Vector3d u = f.now.position[static_cast<size_t>(i)] - f.rest.position[static_cast<size_t>(i)];
    const Eigen::Vector3d expected = f.rest.position[static_cast<size_t>(i)] + 3.0 * u;
    EXPECT_NEAR((mesh.position(i).cast<double>() - expected).norm(), 0.0, 1e-5) << i;
    EXPECT_NEAR(mesh.scalar(i), u.norm(), 1e-5) << i;
  }
  EXPECT_EQ(mesh.indices.size(), 6U * 4U * 5U);  // two triangles per cell
  f.now.valid[0] = 0;                           // a corner marker: one cell goes
  EXPECT_EQ(deformationSurface(f.now, f.rest, o).indices.size(), 6U * (4U * 5U - 1U));
  f.now.valid[14] = 0;                          // an inner marker: four more cells go
  EXPECT_EQ(deformationSurface(f.now, f.rest, o).indices.size(), 6U * (4U * 5U - 5U));
}

TEST(FieldGeometry, FlatSurfaceNormalsPointOutOfThePad) {
  Fields f;
  const MeshVertices mesh = deformationSurface(f.rest, f.rest, {});
  for (int i = 0; i < mesh.count(); ++i) {
    const auto base = static_cast<size_t>(i * MeshVertices::kFloats);
    EXPECT_NEAR(mesh.data[base + 5], 1.0F, 1e-6) << "normal z of vertex " << i;
  }
}

TEST(FieldGeometry, ArrowsFollowTheTangentialDisplacement) {
  Fields f;
  for (int id = 0; id < f.rest.size(); ++id)
    f.now.set(id, f.rest.position[static_cast<size_t>(id)] + Eigen::Vector3d(0.1, -0.05, -0.3));
  FieldGeometryOptions o;
  o.arrow_gain = 5.0;
  const PointVertices arrows = displacementArrows(f.now, f.rest, o);
  ASSERT_EQ(arrows.count(), 30 * 6);  // shaft and two head strokes per marker
  for (int a = 0; a < 30; ++a) {
    const Eigen::Vector3f shaft = arrows.position(6 * a + 1) - arrows.position(6 * a);
    EXPECT_NEAR(shaft.x(), 0.5F, 1e-5);
    EXPECT_NEAR(shaft.y(), -0.25F, 1e-5);
    EXPECT_NEAR(shaft.z(), 0.0F, 1e-6);
  }
  f.now = f.rest;  // no motion, no arrows
  EXPECT_EQ(displacementArrows(f.now, f.rest, o).count(), 0);
}

TEST(FieldGeometry, ContactMapColoursFollowTheStickSlipLabels) {
  Fields f;
  contact::ContactField field;
  field.region_of.assign(30, -1);
  field.region_of[3] = field.region_of[4] = field.region_of[5] = 0;
  pose::PoseStep step;
  step.labels.assign(30, contact::MarkerLabel::outside);
  step.labels[3] = contact::MarkerLabel::stick;
  step.labels[4] = contact::MarkerLabel::slip;
  const PointVertices map = contactMap(f.now, f.rest, field, step);
  ASSERT_EQ(map.count(), 30);
  EXPECT_EQ(map.colour(3), stickColour());
  EXPECT_EQ(map.colour(4), slipColour());
  EXPECT_NE(map.colour(5), stickColour());
  EXPECT_NE(map.colour(5), map.colour(0));  // in the region, unlabelled: not "outside"
  EXPECT_EQ(map.position(3).z(), 0.0F);
  EXPECT_NEAR(map.position(3).x(), f.rest.position[3].x(), 1e-6);
}

TEST(CameraMarkers, ViewPointsMapBackToTheRawFrame) {
  StereoCalibration c;
  c.image_width = 1920, c.split_x = 960, c.flip_left = true, c.flip_right = false;
  EXPECT_EQ(framePixel({0, 5}, false, c), cv::Point2f(959, 5));
  EXPECT_EQ(framePixel({959, 5}, false, c), cv::Point2f(0, 5));
  EXPECT_EQ(framePixel({10, 7}, true, c), cv::Point2f(970, 7));
  c.flip_right = true;
  EXPECT_EQ(framePixel({10, 7}, true, c), cv::Point2f(960 + 949, 7));
}

TEST(CameraMarkers, MeasuredMarkersAreDiscsLostOnesRingsUnseenOnesAbsent) {
  MarkerPattern p{2, 3, 1.0};
  vision::ViewMarkers left(p), right(p);
  left.set(0, {100, 50});
  left.set(4, {120, 60});
  left.clear(4);  // seen before, lost now
  right.set(2, {30, 40});
  StereoCalibration c;
  const PointVertices pts = cornerPoints(left, right, c, 6.0F);
  ASSERT_EQ(pts.count(), 3);
  EXPECT_FALSE(pts.ring(0));
  EXPECT_TRUE(pts.ring(1));
  EXPECT_FALSE(pts.ring(2));
  EXPECT_EQ(pts.colour(0), markerIdColour(0, 2, 3));
  EXPECT_EQ(pts.colour(2), markerIdColour(2, 2, 3));
  EXPECT_NE(markerIdColour(0, 2, 3), markerIdColour(2, 2, 3));  // ids differ in colour
}

}  // namespace
}  // namespace onetip::viewer
