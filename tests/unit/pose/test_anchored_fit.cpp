// The stick fit over anchored markers and the cap that may carry it
// (pose/anchored_fit.hpp), on a 3 x 3 lattice at 2 mm anchored at rest under
// the identity pose, then moved by known presses. Ground truth: the press
// each group of markers was given.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "pose/anchored_fit.hpp"

using namespace onetip;

namespace {

constexpr int kSide = 3, kCount = kSide * kSide;
constexpr double kPitchMm = 2.0;

struct Scene {
  contact::StickSlipClassifier classifier;
  contact::ContactField field;
  MarkerField rest{kSide, kSide}, now{kSide, kSide};
  pose::EstimatorThresholds thresholds;
  std::vector<int> all;
};

// Every marker pressed by `press_mm` (along -S.z), those in `deeper` by `deeper_mm`.
Scene pressed(double press_mm, const std::vector<int>& deeper, double deeper_mm) {
  Scene s;
  s.field.displacement.assign(kCount, Eigen::Vector3d::Zero());
  s.field.normal.assign(kCount, Eigen::Vector3d::UnitZ());
  s.field.valid.assign(kCount, 1);
  for (int id = 0; id < kCount; ++id) {
    const auto i = static_cast<size_t>(id);
    s.rest.position[i] = {kPitchMm * (id % kSide), kPitchMm * (id / kSide), 0.0};
    s.rest.valid[i] = s.now.valid[i] = 1;
    const bool deep = std::find(deeper.begin(), deeper.end(), id) != deeper.end();
    s.field.displacement[i] = {0.0, 0.0, -(deep ? deeper_mm : press_mm)};
    s.now.position[i] = s.rest.position[i] + s.field.displacement[i];
    s.all.push_back(id);
  }
  s.classifier.reset(kCount);
  s.classifier.anchorNew(s.all, s.rest, Eigen::Isometry3d::Identity());
  s.thresholds.noise_mm = 0.001;
  s.thresholds.slip_mm = 0.01;
  s.thresholds.robust_mm = 0.005;
  s.thresholds.min_spread_mm = 1.0;
  return s;
}

std::vector<std::uint8_t> capOf(const std::vector<int>& ids) {
  std::vector<std::uint8_t> cap(kCount, 0);
  for (int id : ids) cap[static_cast<size_t>(id)] = 1;
  return cap;
}

pose::AnchoredFit fitOnTheCap(Scene& s, std::vector<int>& ids, const std::vector<std::uint8_t>& cap) {
  return pose::fitAnchoredOnTheCap(s.classifier, s.field, ids, cap, s.now, Eigen::Isometry3d::Identity(), s.thresholds,
                                   {3.0, 5.0, 3.0});
}

}  // namespace

TEST(AnchoredFit, TheTrimFollowsTheMajority) {
  // Two markers pressed 0.3 mm, seven 0.15 mm: without a cap the fit keeps the seven.
  Scene s = pressed(0.15, {4, 5}, 0.30);
  std::vector<int> ids = s.all;
  const pose::AnchoredFit fit = fitOnTheCap(s, ids, {});
  ASSERT_TRUE(fit.fit.ok);
  EXPECT_NEAR(fit.fit.motion.translation().z(), -0.15, 1e-6);
  EXPECT_EQ(ids.size(), 7u);
}

TEST(AnchoredFit, ACapTheTrimDropsWholeCarriesTheFit) {
  // The same press with the two deeper markers the dimple's cap: they are the touch, the seven the skin beside it.
  Scene s = pressed(0.15, {4, 5}, 0.30);
  std::vector<int> ids = s.all;
  const pose::AnchoredFit fit = fitOnTheCap(s, ids, capOf({4, 5}));
  ASSERT_TRUE(fit.fit.ok);
  EXPECT_NEAR(fit.fit.motion.translation().z(), -0.30, 1e-6);
  EXPECT_EQ(ids, (std::vector<int>{4, 5}));
}

TEST(AnchoredFit, ACapMarkerTrimmedAloneLeavesTheFitAsItIs) {
  // A cap of four whose one marker is pushed 0.2 mm further (it begins to move off the finger): the trim drops
  // that one, three of the cap's four stay, and the fit over the eight agreeing markers stands.
  Scene s = pressed(0.20, {4}, 0.40);
  std::vector<int> ids = s.all;
  const pose::AnchoredFit fit = fitOnTheCap(s, ids, capOf({1, 3, 4, 5}));
  ASSERT_TRUE(fit.fit.ok);
  EXPECT_NEAR(fit.fit.motion.translation().z(), -0.20, 1e-6);
  EXPECT_EQ(ids.size(), 8u);
}

namespace {

// The six markers of rows 0 and 1 (a stripe 4 mm long along S.x, RMS extents 1.63 and 1.0 mm), anchored at rest,
// turned by `tilt_deg` about S.x through their centre; `pushed_mm` more along -S.z on marker 1 (the middle of
// row 0: no rigid motion takes that up). The min spread (1.5 mm) makes the stripe thin. Its turn about its line has noise sqrt(2) 0.001 / (1.0 sqrt 6) = 0.033 deg.
Scene stripeTurned(double tilt_deg, double pushed_mm) {
  Scene s = pressed(0.0, {}, 0.0);
  s.thresholds.min_spread_mm = 1.5;
  s.all = {0, 1, 2, 3, 4, 5};
  const Eigen::Vector3d centre(2.0, 1.0, 0.0);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(tilt_deg * M_PI / 180.0, Eigen::Vector3d::UnitX()).toRotationMatrix();
  for (int id : s.all) {
    const auto i = static_cast<size_t>(id);
    const Eigen::Vector3d push(0, 0, id == 1 ? pushed_mm : 0.0);
    s.now.position[i] = centre + turn * (s.rest.position[i] - centre) - push;
    s.field.displacement[i] = s.now.position[i] - s.rest.position[i];
  }
  return s;
}

double turnAboutX(const pose::AnchoredFit& fit) {
  const Eigen::AngleAxisd aa(fit.fit.motion.linear());
  return aa.angle() * aa.axis().x() * 180.0 / M_PI;
}

}  // namespace

TEST(AnchoredFit, AThinSetThatTurnsRigidlyAboutItsOwnLineFixesAGeneralRotation) {
  Scene s = stripeTurned(0.5, 0.0);  // 15 sigma
  std::vector<int> ids = s.all;
  const pose::AnchoredFit fit = fitOnTheCap(s, ids, {});
  ASSERT_TRUE(fit.fit.ok);
  EXPECT_TRUE(fit.rotation_supported);
  EXPECT_NEAR(turnAboutX(fit), 0.5, 1e-6);
  EXPECT_EQ(ids.size(), 6u);
}

TEST(AnchoredFit, AThinSetsTurnWithinItsNoiseIsNotApplied) {
  // 0.1 deg is 3 of the turn's sigmas, below the 5 asked: the stripe fixes a rotation about S.z only.
  Scene s = stripeTurned(0.1, 0.0);
  std::vector<int> ids = s.all;
  const pose::AnchoredFit fit = fitOnTheCap(s, ids, {});
  ASSERT_TRUE(fit.fit.ok);
  EXPECT_FALSE(fit.rotation_supported);
  EXPECT_NEAR(turnAboutX(fit), 0.0, 1e-9);
}

TEST(AnchoredFit, AThinSetThatDoesNotMoveAsOneBodyIsNotTrustedToTurn) {
  // The same 0.5 deg with one marker pushed 0.008 mm further (under the 0.01 mm slip trim, so kept): its
  // residual exceeds 3 sigma, and the stripe does not fix a general rotation.
  Scene s = stripeTurned(0.5, 0.008);
  std::vector<int> ids = s.all;
  const pose::AnchoredFit fit = fitOnTheCap(s, ids, {});
  ASSERT_TRUE(fit.fit.ok);
  EXPECT_EQ(ids.size(), 6u);
  EXPECT_FALSE(fit.rotation_supported);
  EXPECT_NEAR(turnAboutX(fit), 0.0, 1e-9);
  // Rigid again, it does.
  Scene rigid = stripeTurned(0.5, 0.0);
  std::vector<int> all = rigid.all;
  EXPECT_TRUE(fitOnTheCap(rigid, all, {}).rotation_supported);
}
