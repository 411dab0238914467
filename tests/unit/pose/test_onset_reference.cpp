// c0 (pose/onset_reference.hpp) on synthetic deformation fields over a 15 x 15
// lattice at 1.2 mm: a finger that landed while sliding in -x (a cap of normal
// deformation, and the skin behind it dragged along x), and a second finger far
// off. Expected values are computed here from the paper's definition, marker by
// marker.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "pose/onset_reference.hpp"

using namespace onetip;

namespace {

constexpr int kN = 15;
constexpr double kPitch = 1.2;

struct Onset {
  contact::ContactField field;
  MarkerField now{kN, kN};
  std::vector<int> region;  // the contact stage's region: normal deformation >= 40 % of its peak, first finger
  Eigen::Vector3d rest(int id) const {
    return Eigen::Vector3d((id % kN - kN / 2) * kPitch, (id / kN - kN / 2) * kPitch, 0);
  }
};

// Cap n = 0.6 - r^2 / 8 (mm) around (cx, cy); skin dragged by 0.5 exp(-|y|) mm along -x over the 4 mm behind
// the first finger (x > cx), none under the second.
Onset landing(bool second_finger) {
  Onset o;
  const int n = kN * kN;
  o.field.displacement.assign(n, Eigen::Vector3d::Zero());
  o.field.valid.assign(n, 1);
  for (int id = 0; id < n; ++id) {
    const Eigen::Vector3d p = o.rest(id);
    const double r1 = std::hypot(p.x(), p.y()), r2 = std::hypot(p.x() + 6.0, p.y() + 6.0);
    double nd = std::max(0.0, 0.6 - r1 * r1 / 8);
    if (second_finger) nd = std::max(nd, 0.6 - r2 * r2 / 8);
    Eigen::Vector3d u(0, 0, -nd);
    if (p.x() > 0 && p.x() <= 4.0 && std::abs(p.y()) < 2.0) u.x() = -0.5 * std::exp(-std::abs(p.y()));
    o.field.displacement[static_cast<size_t>(id)] = u;
    o.now.set(id, p + u);
    if (nd >= 0.4 * 0.6 && r1 < 3.0) o.region.push_back(id);
    o.field.max_normal_mm = std::max(o.field.max_normal_mm, nd);  // as the contact stage sets it
  }
  return o;
}

// The paper's region's rest centroid (markers with |u| >= 0.5 max |u.z|): over the whole pad, or only within
// 4.5 mm of the first finger.
Eigen::Vector3d expectedCentroid(const Onset& o, bool first_finger_only) {
  double max_normal = 0;
  for (const auto& u : o.field.displacement) max_normal = std::max(max_normal, std::abs(u.z()));
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int count = 0;
  for (int id = 0; id < kN * kN; ++id) {
    if (o.field.displacement[static_cast<size_t>(id)].norm() < 0.5 * max_normal) continue;
    if (first_finger_only && o.rest(id).norm() > 4.5) continue;
    sum += o.rest(id), ++count;
  }
  return sum / count;
}

Eigen::Vector3d regionCentroid(const Onset& o) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int id : o.region) sum += o.rest(id);
  return sum / static_cast<double>(o.region.size());
}

}  // namespace

TEST(OnsetReference, TheCentroidOfThePapersRegionIncludesTheSkinDraggedBehindALandingFinger) {
  const Onset o = landing(false);
  const Eigen::Vector3d c0 = pose::onsetReferencePoint(o.field, o.now, o.region, regionCentroid(o));
  const Eigen::Vector3d expected = expectedCentroid(o, false);
  EXPECT_LT((c0 - expected).norm(), 1e-9);
  // The reason it exists: the contact stage's region centroid is elsewhere.
  EXPECT_GT((regionCentroid(o) - expected).norm(), 0.2);
  EXPECT_GT(c0.x(), 0.2);  // pulled towards the dragged skin, +x
}

TEST(OnsetReference, AnotherFingersMarkersStayOutAndNoLatticeTakesEveryMarkerThatPasses) {
  const Onset o = landing(true);
  const Eigen::Vector3d c0 = pose::onsetReferencePoint(o.field, o.now, o.region, regionCentroid(o));
  EXPECT_LT((c0 - expectedCentroid(o, true)).norm(), 1e-9);
  MarkerField unstructured = o.now;
  unstructured.rows = unstructured.cols = 0;  // no lattice: connectivity unknown
  const Eigen::Vector3d both = pose::onsetReferencePoint(o.field, unstructured, o.region, regionCentroid(o));
  EXPECT_LT((both - expectedCentroid(o, false)).norm(), 1e-9);
  EXPECT_LT(both.x(), c0.x() - 1.0);  // pulled towards the second finger at (-6, -6)
}

TEST(OnsetReference, NothingMeasuredGivesTheFallback) {
  Onset o = landing(false);
  for (auto& v : o.now.valid) v = 0;
  const Eigen::Vector3d fallback(1, 2, 3);
  EXPECT_EQ(pose::onsetReferencePoint(o.field, o.now, o.region, fallback), fallback);
}
