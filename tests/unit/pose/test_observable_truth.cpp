// The observable reference (observable_truth.hpp) on synthetic contacts: the
// turn is held and the footprint followed while every contact marker slips,
// and the offset that leaves is carried to the end of the contact.
#include <gtest/gtest.h>

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
      truthFrame(ContactState::stick, 1.0, 6.0, 0.6, 1.1),  // sticks again: truth plus the offset
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
  EXPECT_NEAR(o[4].yaw, 6.0 - 4.0, 1e-12);  // 4 deg unseen
  EXPECT_NEAR(o[4].dx, 1.0 - 0.4, 1e-12);   // 0.4 mm of the slide unseen
  EXPECT_NEAR(o[4].dz, 1.1, 1e-12);
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

TEST(ObservableTruth, AFrameWhereNoMarkerSticksIsUnseenEvenIfTheModelsNodesBetweenThemStick) {
  std::vector<ReplayFrame> frames = {truthFrame(ContactState::stick, 0.0, 0.0, 0.0),
                                     truthFrame(ContactState::partial_slip, 0.3, 2.0, 0.1),
                                     truthFrame(ContactState::stick, 0.4, 2.5, 0.2)};
  frames[1].gt_slip = {1, 1};  // the contact model's state says partial slip, but every touching marker slips
  ASSERT_TRUE(everyContactMarkerSlips(frames[1]));
  ASSERT_FALSE(everyContactMarkerSlips(frames[0]));
  const std::vector<Input6> o = observableTruth(frames);
  EXPECT_NEAR(o[1].yaw, 0.0, 1e-12);   // held
  EXPECT_NEAR(o[1].dx, 0.1, 1e-12);    // the footprint's move
  EXPECT_NEAR(o[2].yaw, 0.5, 1e-12);   // 2 deg unseen, carried
  EXPECT_NEAR(o[2].dx, 0.2, 1e-12);
}
