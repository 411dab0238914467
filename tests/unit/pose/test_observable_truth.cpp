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

namespace {

// A contact whose markers all stick, at `points` (S, mm) in every frame, the finger's true motion since onset
// T_k = `motions`[k] about c0 = 0, so each sticking marker's true position moves with it.
std::vector<ReplayFrame> stuckContact(const std::vector<Eigen::Vector3d>& points,
                                      const std::vector<Eigen::Isometry3d>& motions) {
  std::vector<ReplayFrame> frames;
  for (const Eigen::Isometry3d& T : motions) {
    ReplayFrame f = truthFrame(ContactState::stick, 0, 0, 0);
    f.gt = input6FromMotion(T, f.gt_c0);
    f.gt_contact_markers.assign(points.size(), 1);
    f.gt_slip.assign(points.size(), 0);
    for (const Eigen::Vector3d& q : points) f.gt_positions.push_back(T * q);
    frames.push_back(f);
  }
  return frames;
}

Eigen::Isometry3d turnAbout(const Eigen::Vector3d& point, const Eigen::Vector3d& axis, double deg) {
  return Eigen::Translation3d(point) * Eigen::AngleAxisd(deg * kRadPerDeg, axis.normalized()) *
         Eigen::Translation3d(-point);
}

const ObservableTruthOptions kStrict{UnseenMotion::unfixed_directions, 0.0006};

}  // namespace

TEST(ObservableTruthStrict, OneStickingMarkerFixesItsPointButNotTheTurnAboutIt) {
  // The finger turns 6 deg about a tilted axis through the one marker that sticks while sliding 0.3 mm: the
  // strict reference moves that marker exactly as the truth does and holds the turn; issue 40's judge, which
  // counts one sticking marker as seeing everything, follows the truth.
  const Eigen::Vector3d q(1.0, -0.5, 0.2);
  std::vector<Eigen::Isometry3d> motions;
  for (int k = 0; k <= 6; ++k)
    motions.push_back(Eigen::Translation3d(0.05 * k, 0, 0) * turnAbout(q, {0.3, 0.2, 1.0}, 1.0 * k));
  const std::vector<ReplayFrame> frames = stuckContact({q}, motions);
  const std::vector<Input6> strict = observableTruth(frames, kStrict), loose = observableTruth(frames);
  for (size_t k = 0; k < frames.size(); ++k) {
    const Eigen::Isometry3d reference = motionFromInput6(strict[k], frames[k].gt_c0);
    EXPECT_NEAR(Eigen::AngleAxisd(reference.linear()).angle(), 0.0, 1e-9) << "frame " << k;
    EXPECT_NEAR((reference * q - motions[k] * q).norm(), 0.0, 1e-9) << "frame " << k;
    EXPECT_NEAR(loose[k].yaw, frames[k].gt.yaw, 1e-9);
  }
  EXPECT_GT(std::abs(frames.back().gt.yaw), 4.0);
}

TEST(ObservableTruthStrict, ALineOfStickingMarkersHidesOnlyTheTurnAboutTheLine) {
  // Three markers on a line along S.x stick while the finger rolls about that line (4 deg) and pitches about
  // S.y through the line's centre (3 deg): the reference holds the roll and follows the pitch.
  const std::vector<Eigen::Vector3d> line = {{-1.2, 0.4, 0.1}, {0.0, 0.4, 0.1}, {1.2, 0.4, 0.1}};
  const Eigen::Vector3d centre = line[1];
  std::vector<Eigen::Isometry3d> motions, seen;
  for (int k = 0; k <= 4; ++k) {
    const Eigen::Isometry3d pitch = turnAbout(centre, Eigen::Vector3d::UnitY(), 0.75 * k);
    motions.push_back(pitch * turnAbout(centre, Eigen::Vector3d::UnitX(), 1.0 * k));
    seen.push_back(pitch);
  }
  const std::vector<ReplayFrame> frames = stuckContact(line, motions);
  const std::vector<Input6> strict = observableTruth(frames, kStrict);
  for (size_t k = 0; k < frames.size(); ++k) {
    const Eigen::Isometry3d reference = motionFromInput6(strict[k], frames[k].gt_c0);
    // The roll and the pitch do not commute, so the held roll's offset is exact only to second order in the
    // small angles per frame (1 and 0.75 deg): 0.02 deg after four frames.
    EXPECT_NEAR(Eigen::AngleAxisd(reference.linear() * seen[k].linear().transpose()).angle() * kDegPerRad, 0.0,
                0.05) << "frame " << k;
    for (const Eigen::Vector3d& q : line) EXPECT_NEAR((reference * q - motions[k] * q).norm(), 0.0, 1e-3);
  }
}

TEST(ObservableTruthStrict, ThreeMarkersOffALineFixEveryDirection) {
  const std::vector<Eigen::Vector3d> triangle = {{-1.2, 0.0, 0.1}, {1.2, 0.0, 0.1}, {0.0, 1.2, 0.1}};
  std::vector<Eigen::Isometry3d> motions;
  for (int k = 0; k <= 4; ++k)
    motions.push_back(Eigen::Translation3d(0.1 * k, -0.05 * k, 0.02 * k) * turnAbout({0, 0, 8}, {1, 2, 3}, 1.5 * k));
  const std::vector<ReplayFrame> frames = stuckContact(triangle, motions);
  const std::vector<Input6> strict = observableTruth(frames, kStrict);
  for (size_t k = 0; k < frames.size(); ++k)
    for (size_t a = 0; a < 6; ++a) EXPECT_NEAR(strict[k].asArray()[a], frames[k].gt.asArray()[a], 1e-9);
}
