// The observable reference (observable_truth.hpp) on synthetic contacts: the
// turn is held and the footprint followed while every contact marker slips,
// and the offset that leaves is carried to the end of the contact.
#include <gtest/gtest.h>

#include "core/rotation.hpp"
#include "observable_truth.hpp"

using namespace onetip;
using namespace onetip::poseval;

namespace {

// Two markers touch: both stick (stick), one slips (partial slip) or both slip (slip).
ReplayFrame truthFrame(ContactState state, double dx, double yaw, double footprint_x, double dz = 1.0) {
  ReplayFrame f;
  f.gt_contact = true;
  f.gt_state = state;
  f.gt_contact_markers = {1, 1};
  f.gt_slip = {static_cast<std::uint8_t>(state == ContactState::slip ? 1 : 0),
               static_cast<std::uint8_t>(state == ContactState::stick ? 0 : 1)};
  f.gt.dx = dx;
  f.gt.yaw = yaw;
  f.gt.dz = dz;
  f.gt_footprint = {footprint_x, 0};
  f.gt_footprint_valid = true;
  return f;
}

}  // namespace

TEST(ObservableTruth, GrossSlipHoldsTheTurnFollowsTheFootprintAndCarriesTheOffset) {
  std::vector<ReplayFrame> frames = {
      truthFrame(ContactState::stick, 0.0, 0.0, 0.0),
      truthFrame(ContactState::partial_slip, 0.1, 1.0, 0.1),
      truthFrame(ContactState::slip, 0.5, 3.0, 0.3, 1.2),  // the finger slides 0.4 and turns 2 deg; the footprint moves 0.2
      truthFrame(ContactState::slip, 0.9, 5.0, 0.5, 1.2),
      truthFrame(ContactState::stick, 1.0, 6.0, 0.6, 1.1),  // sticks again, but only just: still unseen
      truthFrame(ContactState::stick, 1.1, 6.0, 0.7, 1.1),  // stuck through the interval: truth plus the offset
  };
  const std::vector<Input6> o = observableTruth(frames);
  ASSERT_EQ(o.size(), frames.size());
  EXPECT_DOUBLE_EQ(o[1].dx, 0.1);
  EXPECT_DOUBLE_EQ(o[1].yaw, 1.0);
  EXPECT_NEAR(o[2].yaw, 1.0, 1e-12);
  EXPECT_NEAR(o[2].dx, 0.3, 1e-12);
  EXPECT_NEAR(o[2].dz, 1.2, 1e-12);  // the depth stays observable
  EXPECT_NEAR(o[3].yaw, 1.0, 1e-12);
  EXPECT_NEAR(o[3].dx, 0.5, 1e-12);
  EXPECT_NEAR(o[4].yaw, 1.0, 1e-12);
  EXPECT_NEAR(o[4].dx, 0.6, 1e-12);
  EXPECT_NEAR(o[5].yaw, 6.0 - 5.0, 1e-12);  // 5 deg unseen
  EXPECT_NEAR(o[5].dx, 1.1 - 0.4, 1e-12);   // 0.4 mm of the slide unseen
  EXPECT_NEAR(o[5].dz, 1.1, 1e-12);
}

TEST(ObservableTruth, ANewContactStartsFromTheTruthAgain) {
  std::vector<ReplayFrame> frames = {truthFrame(ContactState::stick, 0, 0, 0), truthFrame(ContactState::slip, 1, 9, 0)};
  ReplayFrame lifted;  // out of contact
  frames.push_back(lifted);
  frames.push_back(truthFrame(ContactState::stick, 0.2, 0.5, 0));
  const std::vector<Input6> o = observableTruth(frames);
  EXPECT_NEAR(o[1].yaw, 0, 1e-12);
  EXPECT_DOUBLE_EQ(o[3].yaw, 0.5);
  EXPECT_DOUBLE_EQ(o[3].dx, 0.2);
}

TEST(ObservableTruth, AnIntervalNoMarkerSticksThroughIsUnseenEvenIfTheModelsNodesBetweenThemStick) {
  std::vector<ReplayFrame> frames = {truthFrame(ContactState::stick, 0.0, 0.0, 0.0),
                                     truthFrame(ContactState::partial_slip, 0.3, 2.0, 0.1),
                                     truthFrame(ContactState::partial_slip, 0.4, 2.5, 0.2),
                                     truthFrame(ContactState::stick, 0.5, 2.5, 0.3)};
  frames[0].gt_slip = {0, 1};  // marker 0 sticks
  frames[1].gt_slip = {1, 0};  // ... then slips while marker 1 sticks: the model's state says partial slip
  frames[2].gt_slip = {1, 0};  // marker 1 sticks through: seen again
  ASSERT_TRUE(noMarkerSticksThrough(frames[0], frames[1]));
  ASSERT_FALSE(noMarkerSticksThrough(frames[1], frames[2]));
  const std::vector<Input6> o = observableTruth(frames);
  EXPECT_NEAR(o[1].yaw, 0.0, 1e-12);  // held
  EXPECT_NEAR(o[1].dx, 0.1, 1e-12);   // the footprint's move
  EXPECT_NEAR(o[2].yaw, 0.5, 1e-12);  // the 2 deg unseen, carried
  EXPECT_NEAR(o[2].dx, 0.2, 1e-5);  // the seen 0.5 deg turns the 0.1 mm offset too (about c0 = 0)
  EXPECT_NEAR(o[3].yaw, 0.5, 1e-12);
  EXPECT_NEAR(o[3].dx, 0.3, 1e-5);
}

TEST(ObservableTruth, ATurnHeldOnceStaysTheSameTurnWhileTheFingerThenTurnsAboutAnotherAxis) {
  // 10 deg of yaw unseen, then 30 deg of pitch seen: an estimate that holds the yaw and follows every seen
  // interval is off by the same 10 deg turn throughout, which the reference must say (six numbers carried as
  // a constant difference would not: Euler angles do not add).
  std::vector<ReplayFrame> frames = {truthFrame(ContactState::stick, 0, 0, 0), truthFrame(ContactState::slip, 0, 10, 0),
                                     truthFrame(ContactState::stick, 0, 10, 0)};  // sticks again: still unseen
  for (int k = 1; k <= 6; ++k) {
    frames.push_back(truthFrame(ContactState::stick, 0, 10, 0));
    frames.back().gt.pitch = 5.0 * k;
  }
  const std::vector<Input6> o = observableTruth(frames);
  for (size_t k = 2; k < frames.size(); ++k) {
    const Eigen::Isometry3d truth = motionFromInput6(frames[k].gt, frames[k].gt_c0);
    const Eigen::Isometry3d reference = motionFromInput6(o[k], frames[k].gt_c0);
    EXPECT_NEAR(Eigen::AngleAxisd(truth.linear() * reference.linear().transpose()).angle() * kDegPerRad, 10.0, 1e-9)
        << "frame " << k;
  }
}
