// The contact cap (pose/contact_cap.hpp) on synthetic dimples of known shape:
// its curvature and the rolling shift that follows from it.
#include <gtest/gtest.h>

#include <cmath>

#include "pose/contact_cap.hpp"

using namespace onetip::pose;

namespace {

// Markers on a 1.2 mm grid pressed into the shape z = 1/2 x^T H x - depth
// within `radius` of `centre` (S, mm), normal deformation = depth - 1/2 x^T H x.
void dimple(const Eigen::Matrix2d& h, const Eigen::Vector2d& centre, double depth, double radius,
            std::vector<Eigen::Vector3d>& p, std::vector<double>& n) {
  for (int r = -8; r <= 8; ++r)
    for (int c = -8; c <= 8; ++c) {
      const Eigen::Vector2d x(1.2 * c, 1.2 * r);
      const Eigen::Vector2d d = x - centre;
      if (d.norm() > radius) continue;
      const double z = 0.5 * d.dot(h * d) - depth;
      p.emplace_back(x.x(), x.y(), z);
      n.push_back(-z);
    }
}

}  // namespace

TEST(ContactCap, RecoversTheCurvatureOfASphereAndItsRollingShift) {
  const double radius = 8.0;  // mm: the sphere the skin conforms to
  std::vector<Eigen::Vector3d> p;
  std::vector<double> n;
  dimple(Eigen::Matrix2d::Identity() / radius, {0.3, -0.2}, 1.0, 4.0, p, n);
  const ContactCap cap = fitContactCap(p, n, 0.4);
  ASSERT_TRUE(cap.valid);
  EXPECT_NEAR(cap.curvature(0, 0), 1 / radius, 1e-9);
  EXPECT_NEAR(cap.curvature(1, 1), 1 / radius, 1e-9);
  EXPECT_NEAR(cap.curvature(0, 1), 0, 1e-9);
  // Rolled by 2 deg about S.y, a sphere's lowest point moves R w along +x.
  const double w = 2.0 * M_PI / 180;
  const Eigen::Vector2d rho = rollingShift(cap, Eigen::Vector3d(0, w, 0));
  EXPECT_NEAR(rho.x(), radius * w, 1e-9);
  EXPECT_NEAR(rho.y(), 0, 1e-9);
  // Pitched about S.x by +w, it moves along -y.
  EXPECT_NEAR(rollingShift(cap, Eigen::Vector3d(w, 0, 0)).y(), -radius * w, 1e-9);
  // A twist about S.z does not move the lowest point.
  EXPECT_NEAR(rollingShift(cap, Eigen::Vector3d(0, 0, w)).norm(), 0, 1e-12);
}

TEST(ContactCap, AnEllipsoidGivesEachAxisItsRadiusAndAFlatCapAHugeOne) {
  // An ellipsoid finger's cap: flatter along y (radius 13.5) than along x (8.2).
  std::vector<Eigen::Vector3d> p;
  std::vector<double> n;
  Eigen::Matrix2d h;
  h << 1 / 8.2, 0, 0, 1 / 13.5;
  dimple(h, {0, 0}, 1.2, 6.0, p, n);
  const ContactCap cap = fitContactCap(p, n, 0.0);
  ASSERT_TRUE(cap.valid);
  EXPECT_NEAR(rollingShift(cap, Eigen::Vector3d(0, 0.01, 0)).x(), 8.2 * 0.01, 1e-9);
  EXPECT_NEAR(rollingShift(cap, Eigen::Vector3d(0.01, 0, 0)).y(), -13.5 * 0.01, 1e-9);
  // A flat plate: the radius is clipped at kMaxCapRadiusMm, so any tilt gives a
  // rolling shift far beyond anything the footprint can tell.
  p.clear();
  n.clear();
  dimple(Eigen::Matrix2d::Zero(), {0, 0}, 0.5, 6.0, p, n);
  const ContactCap flat = fitContactCap(p, n, 0.2);
  ASSERT_TRUE(flat.valid);
  EXPECT_NEAR(rollingShift(flat, Eigen::Vector3d(0, 0.01, 0)).x(), kMaxCapRadiusMm * 0.01, 1e-6);
}

TEST(ContactCap, TooFewMarkersGiveNoCap) {
  std::vector<Eigen::Vector3d> p = {{0, 0, -1}, {1.2, 0, -0.9}, {0, 1.2, -0.9}};
  std::vector<double> n = {1, 0.9, 0.9};
  EXPECT_FALSE(fitContactCap(p, n, 0.4).valid);
  EXPECT_EQ(rollingShift(fitContactCap(p, n, 0.4), Eigen::Vector3d(0, 0.1, 0)).norm(), 0.0);
}
