#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "contact/stick_slip_classifier.hpp"
#include "core/error.hpp"
#include "synthetic_field.hpp"

using namespace onetip;
using contact::MarkerLabel;
using contact::StickSlipClassifier;

namespace {

MarkerField moved(const MarkerField& f, const Eigen::Isometry3d& T) {
  MarkerField out = f;
  for (auto& p : out.position) p = T * p;
  return out;
}

Eigen::Isometry3d motion(double x, double yaw_deg) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(yaw_deg * 3.14159265358979 / 180, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(x, 0, -0.1);
  return T;
}

// A 5 x 5 flat grid, every marker anchored at rest and sticking (hold 3 frames).
struct AnchoredGrid {
  MarkerField rest = synth::flatGrid(5, 5);
  std::vector<int> all;
  std::vector<Eigen::Vector3d> up = std::vector<Eigen::Vector3d>(25, Eigen::Vector3d::UnitZ());
  StickSlipClassifier c{contact::StickSlipOptions{0.01, 3}};
  AnchoredGrid() {
    for (int i = 0; i < 25; ++i) all.push_back(i);
    c.reset(25);
    c.anchorNew(all, rest, Eigen::Isometry3d::Identity());
  }
};

}  // namespace

TEST(StickSlipClassifier, RigidMotionSticksSlidingMarkersSlipAndReturnAfterTheHold) {
  AnchoredGrid g;
  const MarkerField& rest = g.rest;
  const std::vector<Eigen::Vector3d>& up = g.up;
  StickSlipClassifier& c = g.c;

  // Frame 1: the finger moved; marker 0 stayed 0.1 mm behind (slid tangentially).
  const Eigen::Isometry3d T1 = motion(0.3, 2);
  MarkerField f1 = moved(rest, T1);
  f1.position[0] -= Eigen::Vector3d(0.1, 0, 0);
  EXPECT_EQ(c.classify(f1, up, T1), 1);
  EXPECT_EQ(c.label(0), MarkerLabel::slip);
  for (int i = 1; i < 25; ++i) EXPECT_EQ(c.label(i), MarkerLabel::stick);

  // Marker 12 lifts off the finger (normal offset): detached, not slip.
  MarkerField f2 = moved(rest, T1);
  f2.position[0] -= Eigen::Vector3d(0.1, 0, 0);
  f2.position[12] += Eigen::Vector3d(0, 0, 0.1);
  c.classify(f2, up, T1);
  EXPECT_EQ(c.label(12), MarkerLabel::detached);

  // Marker 0 has moved with the finger since frame 1 (re-anchored there): frame 2
  // was its first quiet frame; it sticks again at the third (stick_hold_frames).
  EXPECT_EQ(c.label(0), MarkerLabel::slip);
  c.classify(f2, up, T1);
  EXPECT_EQ(c.label(0), MarkerLabel::slip);
  c.classify(f2, up, T1);
  EXPECT_EQ(c.label(0), MarkerLabel::stick);
}

TEST(StickSlipClassifier, ReattachedMarkersStickAtTheGivenPoseAndTheOthersKeepTheirLabels) {
  AnchoredGrid g;
  // Markers 6 and 7 are pushed 0.1 mm deeper than the finger carries them: detached; marker 0 slides: slip.
  const Eigen::Isometry3d T1 = motion(0.3, 2);
  MarkerField f1 = moved(g.rest, T1);
  f1.position[6] -= Eigen::Vector3d(0, 0, 0.1);
  f1.position[7] -= Eigen::Vector3d(0, 0, 0.1);
  f1.position[0] -= Eigen::Vector3d(0.1, 0, 0);
  g.c.classify(f1, g.up, T1);
  ASSERT_EQ(g.c.label(6), MarkerLabel::detached);
  ASSERT_EQ(g.c.label(0), MarkerLabel::slip);
  // The estimate was 0.1 mm short of the press: reattached under the deeper pose, 6 and 7 stick and sit on
  // their anchors; 0 still slips and 1 still sticks.
  Eigen::Isometry3d T2 = T1;
  T2.translation().z() -= 0.1;
  g.c.reattach({6, 7}, f1, T2);
  EXPECT_EQ(g.c.label(6), MarkerLabel::stick);
  EXPECT_EQ(g.c.label(7), MarkerLabel::stick);
  EXPECT_EQ(g.c.label(0), MarkerLabel::slip);
  EXPECT_EQ(g.c.label(1), MarkerLabel::stick);
  EXPECT_LT((T2 * g.c.anchor(6) - f1.position[6]).norm(), 1e-12);
}

TEST(StickSlipClassifier, RetainForgetsMarkersLeavingTheRegion) {
  const MarkerField rest = synth::flatGrid(3, 3);
  StickSlipClassifier c;
  c.reset(9);
  c.anchorNew({0, 1, 2, 3}, rest, Eigen::Isometry3d::Identity());
  MarkerField now = rest;
  now.valid[1] = 0;
  c.retain({0, 1, 3}, now);
  EXPECT_EQ(c.label(0), MarkerLabel::stick);
  EXPECT_EQ(c.label(1), MarkerLabel::outside);  // lost
  EXPECT_EQ(c.label(2), MarkerLabel::outside);  // left the region
  EXPECT_EQ(c.withLabel(MarkerLabel::stick), (std::vector<int>{0, 3}));
}

// A marker counts the classifications since it joined the contact, whatever its
// label; a marker that leaves the region and comes back starts again.
TEST(StickSlipClassifier, CountsTheFramesEachMarkerHasBeenInTheContact) {
  AnchoredGrid g;
  StickSlipClassifier& c = g.c;
  EXPECT_EQ(c.framesInContact(0), 0);
  const Eigen::Isometry3d T = motion(0.3, 2);
  MarkerField slid = moved(g.rest, T);
  slid.position[0] -= Eigen::Vector3d(0.1, 0, 0);
  c.classify(slid, g.up, T);
  c.classify(slid, g.up, T);
  EXPECT_EQ(c.label(0), MarkerLabel::slip);
  EXPECT_EQ(c.framesInContact(0), 2);
  EXPECT_EQ(c.framesInContact(7), 2);
  std::vector<int> without7 = g.all;
  without7.erase(without7.begin() + 7);
  c.retain(without7, slid);  // measured outside the region: forgotten
  c.classify(slid, g.up, T);
  EXPECT_EQ(c.framesInContact(0), 3);
  c.retain(g.all, slid);
  c.anchorNew(g.all, slid, T);
  EXPECT_EQ(c.framesInContact(7), 0);
  c.classify(slid, g.up, T);
  EXPECT_EQ(c.framesInContact(7), 1);
}

TEST(StickSlipClassifier, OptionsAreValidated) {
  contact::StickSlipOptions o;
  o.slip_threshold_mm = 0;
  EXPECT_THROW(StickSlipClassifier{o}, InputError);
  o = {};
  o.stick_hold_frames = 0;
  EXPECT_THROW(StickSlipClassifier{o}, InputError);
}

// A marker the front end misses for a frame is not a new marker: it comes back
// with the label and anchor it had (here: slipping, 0.1 mm behind its anchor,
// so the next classification still finds it slipping), not as a fresh stick
// marker anchored wherever it reappears. One measured outside the region is
// forgotten and starts again as stick.
TEST(StickSlipClassifier, AMarkerUnmeasuredForAFrameComesBackWithItsLabel) {
  AnchoredGrid g;
  const MarkerField& rest = g.rest;
  const std::vector<int>& all = g.all;
  const std::vector<Eigen::Vector3d>& up = g.up;
  StickSlipClassifier& c = g.c;
  const Eigen::Isometry3d T = motion(0.3, 2);
  MarkerField f1 = moved(rest, T);
  f1.position[0] -= Eigen::Vector3d(0.1, 0, 0);
  c.classify(f1, up, T);
  ASSERT_EQ(c.label(0), MarkerLabel::slip);

  // Frame 2: markers 0 and 6 are not measured (dropped by the front end).
  MarkerField f2 = moved(rest, T);
  f2.valid[0] = f2.valid[6] = 0;
  std::vector<int> seen;
  for (int i : all)
    if (f2.valid[static_cast<size_t>(i)]) seen.push_back(i);
  c.retain(seen, f2);
  EXPECT_EQ(c.label(0), MarkerLabel::outside);
  c.anchorNew(seen, f2, T);

  // Frame 3: both are back; marker 0 has slid a further 0.1 mm behind the finger.
  MarkerField f3 = moved(rest, T);
  f3.position[0] -= Eigen::Vector3d(0.2, 0, 0);
  c.retain(all, f3);
  c.anchorNew(all, f3, T);
  EXPECT_EQ(c.label(0), MarkerLabel::slip);
  EXPECT_EQ(c.label(6), MarkerLabel::stick);
  c.classify(f3, up, T);
  EXPECT_EQ(c.label(0), MarkerLabel::slip);  // 0.1 mm off its old anchor: still slipping
  EXPECT_EQ(c.label(6), MarkerLabel::stick);

  // Marker 0 measured but outside the region for a frame: forgotten, back as stick.
  std::vector<int> without0(all.begin() + 1, all.end());
  c.retain(without0, f3);
  c.retain(all, f3);
  c.anchorNew(all, f3, T);
  EXPECT_EQ(c.label(0), MarkerLabel::stick);
}
