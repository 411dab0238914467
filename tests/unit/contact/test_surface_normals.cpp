#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "contact/surface_normals.hpp"
#include "synthetic_field.hpp"

using namespace onetip;

TEST(SurfaceNormals, TiltedPlaneIsExact) {
  const MarkerField rest = synth::flatGrid(9, 9);
  // z = 0.2 x - 0.1 y: normal (-0.2, 0.1, 1) normalised, pointing to +z.
  const MarkerField f = synth::deformed(rest, [](const Eigen::Vector3d& p) {
    return Eigen::Vector3d(0, 0, 0.2 * p.x() - 0.1 * p.y());
  });
  std::vector<Eigen::Vector3d> n;
  std::vector<std::uint8_t> ok;
  contact::gridSurfaceNormals(f, n, ok);
  const Eigen::Vector3d expected = Eigen::Vector3d(-0.2, 0.1, 1).normalized();
  for (int i = 0; i < f.size(); ++i) {
    ASSERT_TRUE(ok[static_cast<size_t>(i)]);
    EXPECT_NEAR((n[static_cast<size_t>(i)] - expected).norm(), 0, 1e-12);
  }
}

TEST(SurfaceNormals, SphericalDimpleWithinHalfDegreeAlsoNextToALostMarker) {
  // The marker layer shaped as a sphere of radius 10 mm centred above it.
  const double R = 10, depth = 1.0;
  MarkerField f = synth::deformed(synth::flatGrid(17, 17), [&](const Eigen::Vector3d& p) {
    const double r2 = p.x() * p.x() + p.y() * p.y();
    const double z = R - depth - std::sqrt(R * R - r2);  // smooth over the whole grid (r < R)
    return Eigen::Vector3d(0, 0, z);
  });
  f.valid[8 * 17 + 9] = 0;  // a lost marker next to the centre
  std::vector<Eigen::Vector3d> n;
  std::vector<std::uint8_t> ok;
  contact::gridSurfaceNormals(f, n, ok);
  const Eigen::Vector3d centre(0, 0, R - depth);
  int checked = 0;
  for (int i = 0; i < f.size(); ++i) {
    const Eigen::Vector3d& p = f.position[static_cast<size_t>(i)];
    const double r = p.head<2>().norm();
    if (!f.valid[static_cast<size_t>(i)] || r > 3.0) continue;  // well inside the cap
    ASSERT_TRUE(ok[static_cast<size_t>(i)]);
    const Eigen::Vector3d truth = (centre - p).normalized();
    EXPECT_LT(std::acos(std::min(1.0, truth.dot(n[static_cast<size_t>(i)]))) * 57.2958, 0.5) << "marker " << i;
    ++checked;
  }
  EXPECT_GE(checked, 20);
}
