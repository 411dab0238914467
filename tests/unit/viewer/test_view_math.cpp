// Camera matrices, panel layout and the input object's pose against
// independent references (Eigen's own transforms, core/rotation.hpp).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/error.hpp"
#include "core/rotation.hpp"
#include "viewer/gl_math.hpp"
#include "viewer/input_object.hpp"
#include "viewer/panel_layout.hpp"

namespace onetip::viewer {
namespace {

Eigen::Vector3f project(const Eigen::Matrix4f& m, const Eigen::Vector3f& p) {
  const Eigen::Vector4f c = m * p.homogeneous();
  return c.head<3>() / c.w();
}

TEST(ViewMath, LookAtPutsTheEyeAtTheOriginLookingDownMinusZ) {
  const Eigen::Vector3f eye(3, -20, 15), target(0, 1, -1);
  const Eigen::Matrix4f v = lookAt(eye, target, {0, 0, 1});
  EXPECT_NEAR(project(v, eye).norm(), 0.0F, 1e-4F);
  const Eigen::Vector3f t = project(v, target);
  EXPECT_NEAR(t.x(), 0.0F, 1e-4F);
  EXPECT_NEAR(t.y(), 0.0F, 1e-4F);
  EXPECT_NEAR(t.z(), -(eye - target).norm(), 1e-4F);
  const Eigen::Matrix3f rotation = v.block<3, 3>(0, 0);
  EXPECT_NEAR(rotation.determinant(), 1.0F, 1e-5F);  // a proper rotation
  EXPECT_GT(project(v, target + Eigen::Vector3f(0, 0, 1)).y(), 0.0F);  // up stays up
}

TEST(ViewMath, PerspectiveMapsTheFrustumToTheUnitCube) {
  const Eigen::Matrix4f p = perspective(60.0F, 2.0F, 1.0F, 100.0F);
  EXPECT_NEAR(project(p, {0, 0, -1}).z(), -1.0F, 1e-5F);
  EXPECT_NEAR(project(p, {0, 0, -100}).z(), 1.0F, 1e-4F);
  const float half_h = 10.0F * std::tan(30.0F * static_cast<float>(M_PI) / 180.0F);
  EXPECT_NEAR(project(p, {0, half_h, -10}).y(), 1.0F, 1e-5F);
  EXPECT_NEAR(project(p, {2.0F * half_h, 0, -10}).x(), 1.0F, 1e-5F);
}

TEST(ViewMath, OrthographicAndNdcRectMapPixelsTopDown) {
  const Eigen::Matrix4f o = orthographic(0, 1920, 1080, 0);
  EXPECT_TRUE(project(o, {0, 0, 0}).head<2>().isApprox(Eigen::Vector2f(-1, 1)));
  EXPECT_TRUE(project(o, {1920, 1080, 0}).head<2>().isApprox(Eigen::Vector2f(1, -1)));
  const Eigen::Vector4f r = ndcRect({0, 0, 640, 360}, {1280, 720});
  EXPECT_TRUE(r.isApprox(Eigen::Vector4f(-1, 0, 0, 1)));
}

TEST(PanelLayout, PanelsTileTheWindowWithoutOverlap) {
  const PanelLayout l = PanelLayout::forWindow({1280, 720});
  long area = 0;
  const auto panels = l.panels();
  for (size_t i = 0; i < panels.size(); ++i) {
    const cv::Rect& a = panels[i].second;
    EXPECT_EQ(a & cv::Rect(0, 0, 1280, 720), a) << panels[i].first;
    area += a.area();
    for (size_t j = i + 1; j < panels.size(); ++j) EXPECT_EQ((a & panels[j].second).area(), 0);
  }
  EXPECT_EQ(area, 1280L * 720L);
  EXPECT_THROW(PanelLayout::forWindow({320, 200}), InputError);
  const cv::Rect2d fit = fitInside({1920, 1080}, {0, 0, 400, 400});
  EXPECT_DOUBLE_EQ(fit.width, 400.0);
  EXPECT_DOUBLE_EQ(fit.height, 225.0);
  EXPECT_DOUBLE_EQ(fit.y, 87.5);
}

TEST(InputObject, PoseRecoversTheInputThroughCoreRotation) {
  const Input6 v{1.5, -2.0, 1.0, 10.0, -20.0, 25.0};
  const Eigen::Isometry3d T = inputObjectPose(v, 1.0);
  // The object's origin is its contact point c0 = 0: the 6-D vector of its
  // motion there is the input itself (core's reference implementation).
  const Input6 back = input6FromMotion(T, Eigen::Vector3d::Zero());
  const auto a = v.asArray(), b = back.asArray();
  for (size_t i = 0; i < 6; ++i) EXPECT_NEAR(a[i], b[i], 1e-9) << i;
  const Eigen::Isometry3d magnified = inputObjectPose(v, 2.0);
  EXPECT_TRUE(magnified.translation().isApprox(Eigen::Vector3d(3.0, -4.0, -2.0)));  // dz > 0 sinks
  EXPECT_TRUE(magnified.linear().isApprox(T.linear()));
}

TEST(InputObject, BoxSpansItsSizeAboveThePadWithOutwardNormals) {
  const MeshVertices box = fingerBox({10, 16, 6});
  ASSERT_EQ(box.count(), 24);
  EXPECT_EQ(box.indices.size(), 36U);
  Eigen::Vector3f lo = box.position(0), hi = box.position(0);
  for (int i = 0; i < box.count(); ++i) {
    lo = lo.cwiseMin(box.position(i));
    hi = hi.cwiseMax(box.position(i));
    const auto base = static_cast<size_t>(i * MeshVertices::kFloats);
    const Eigen::Vector3f n(box.data[base + 3], box.data[base + 4], box.data[base + 5]);
    const Eigen::Vector3f from_centre = box.position(i) - Eigen::Vector3f(0, 0, 3);
    EXPECT_GT(n.dot(from_centre), 0.0F) << "vertex " << i;
  }
  EXPECT_TRUE(lo.isApprox(Eigen::Vector3f(-5, -8, 0)));
  EXPECT_TRUE(hi.isApprox(Eigen::Vector3f(5, 8, 6)));
}

}  // namespace
}  // namespace onetip::viewer
