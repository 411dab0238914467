// The creep test (pose/stick_set_creep.hpp) on synthetic frames: slip
// correspondences built from the finger's true motion and a lag or a lead of
// known size, against the motion a stick set reports.
#include <gtest/gtest.h>

#include <cmath>

#include "pose/model_selection.hpp"
#include "pose/stick_set_creep.hpp"

using namespace onetip::pose;

namespace {

constexpr double kNoise = 0.0006;  // marker noise sigma (mm)
constexpr double kSlip = 0.01;     // slip threshold (mm)

Eigen::Isometry3d translation(double x, double y, double z = 0) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(x, y, z);
  return t;
}

// Slip markers on a ring of radius 2 mm around the contact centre, each moved
// by `moved` (S, mm) this frame.
std::vector<SlipCorrespondence> ring(const Eigen::Vector3d& moved) {
  std::vector<SlipCorrespondence> out;
  for (int k = 0; k < 8; ++k) {
    const double a = k * 0.785398;
    const Eigen::Vector3d from(2 * std::cos(a), 2 * std::sin(a), -0.3);
    out.push_back({from, from + moved, Eigen::Vector3d::UnitZ()});
  }
  return out;
}

}  // namespace

// sweep_x's end of stroke: the finger moves 0.05 mm, the stick set crept 0.013
// mm; one marker (the one that still sticks) moved the finger's 0.05 mm.
TEST(StickSetCreep, AMarkerThatKeepsUpWithTheFingerOvertakesACreepingStickSet) {
  std::vector<SlipCorrespondence> slip = ring({0.02, 0, 0});  // lagging skin
  const Eigen::Vector3d centre(0, 0, -0.3);
  slip.push_back({centre, centre + Eigen::Vector3d(0.05, 0, 0), Eigen::Vector3d::UnitZ()});
  EXPECT_TRUE(slipMarkersOvertake(translation(0.013, 0), slip, kNoise, kSlip));
  // Against the finger's own motion the same marker leads by nothing.
  EXPECT_FALSE(slipMarkersOvertake(translation(0.05, 0), slip, kNoise, kSlip));
}

// Partial slip as it should be: the skin lags, whatever the direction of travel.
TEST(StickSetCreep, LaggingSkinNeverOvertakes) {
  for (const Eigen::Vector2d& dir : {Eigen::Vector2d(1, 0), Eigen::Vector2d(0, -1), Eigen::Vector2d(0.6, 0.8)}) {
    const Eigen::Vector2d finger = 0.05 * dir, skin = 0.02 * dir;
    EXPECT_FALSE(slipMarkersOvertake(translation(finger.x(), finger.y()), ring({skin.x(), skin.y(), 0}), kNoise,
                                     kSlip));
  }
  // At a reversal the finger moves back while the skin still moves the old way.
  EXPECT_FALSE(slipMarkersOvertake(translation(-0.05, 0), ring({0.01, 0, 0}), kNoise, kSlip));
}

// A lead only exists along a motion: with the finger still (within the noise
// floor) relaxing skin moves in any direction without overtaking anything.
TEST(StickSetCreep, NoMotionNoLead) {
  EXPECT_FALSE(slipMarkersOvertake(translation(0.001, 0), ring({0.03, 0.03, 0}), kNoise, kSlip));
  EXPECT_FALSE(slipMarkersOvertake(translation(0, 0), ring({-0.03, 0, 0}), kNoise, kSlip));
}

// A press moves markers along the normal by other rules (the skin beside a
// touch dips less than the touch): only the part in the pad's plane counts.
TEST(StickSetCreep, TheNormalPartDoesNotCount) {
  EXPECT_FALSE(slipMarkersOvertake(translation(0.01, 0, -0.05), ring({0.005, 0, -0.2}), kNoise, kSlip));
}

// A lead within the slip threshold is not creep (the skin's own noise and
// elastic give); beyond it, it is.
TEST(StickSetCreep, TheLeadMustExceedTheSlipThreshold) {
  EXPECT_FALSE(slipMarkersOvertake(translation(0.04, 0), ring({0.04 + 0.9 * kSlip, 0, 0}), kNoise, kSlip));
  EXPECT_TRUE(slipMarkersOvertake(translation(0.04, 0), ring({0.04 + 1.1 * kSlip, 0, 0}), kNoise, kSlip));
}

TEST(ModelSelection, ACreepingStickSetIsTreatedAsEquation16Failing) {
  ModelEvidence e;
  e.stick_fit_ok = true;
  e.n_stick = 3;
  e.n_slip = 25;  // 3 * 3 + 25 >= 6: Eq. 16 holds by the count
  EXPECT_EQ(selectModel(e, ModelPolicy::adaptive), PoseModel::kabsch);
  e.stick_set_creeps = true;
  EXPECT_EQ(selectModel(e, ModelPolicy::adaptive), PoseModel::centroid);
}
