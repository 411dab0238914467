// The campaign's judge (campaign_score.hpp) on synthetic frames whose errors
// are known: divergence needs more than three consecutive frames beyond
// 1 mm / 5 deg inside the working range; the linear range bounds the RMSE;
// the truth's turn is summed over its gross-slip frames only.
#include <gtest/gtest.h>

#include "campaign_score.hpp"

using namespace onetip;
using namespace onetip::poseval;

namespace {

ReplayFrame frame(double gt_dx, double est_dx, double gt_pitch = 0, double est_pitch = 0) {
  ReplayFrame f;
  f.gt_contact = f.contact = true;
  f.gt.dx = gt_dx;
  f.raw.dx = est_dx;
  f.gt.pitch = gt_pitch;
  f.raw.pitch = est_pitch;
  return f;
}

}  // namespace

TEST(CampaignScore, DivergenceNeedsMoreThanThreeConsecutiveFrames) {
  std::vector<ReplayFrame> frames(10, frame(0.5, 0.5));
  for (int k = 2; k < 5; ++k) frames[static_cast<size_t>(k)] = frame(0.5, 1.6);  // 3 frames 1.1 mm off
  RunScore s = scoreRun(frames);
  EXPECT_EQ(s.longest_excess, 3);
  EXPECT_FALSE(s.diverged);
  frames[5] = frame(0.5, 1.6);  // now 4
  s = scoreRun(frames);
  EXPECT_EQ(s.longest_excess, 4);
  EXPECT_EQ(s.first_excess_frame, 2);
  EXPECT_EQ(s.excess_axis, 0);
  EXPECT_TRUE(s.diverged);
}

TEST(CampaignScore, OnlyTheWorkingRangeCountsAndAMissedContactIsAnError) {
  std::vector<ReplayFrame> frames(8, frame(0.0, 0.0, 45, 30));  // pitch 45: beyond the range
  EXPECT_FALSE(scoreRun(frames).diverged);
  EXPECT_EQ(scoreRun(frames).working_frames, 0);
  for (auto& f : frames) {
    f = frame(0.0, 0.0, 20, 0);
    f.contact = false;  // the estimate lost the contact: its output counts as zero
  }
  const RunScore s = scoreRun(frames);
  EXPECT_EQ(s.contact_missed, 8);
  EXPECT_TRUE(s.diverged);
  EXPECT_EQ(s.excess_axis, 4);
  EXPECT_NEAR(s.linear_rmse[4], 20.0, 1e-12);
}

TEST(CampaignScore, TheLinearRangeStopsAtOnePointFiveMillimetres) {
  std::vector<ReplayFrame> frames = {frame(1.0, 1.1), frame(2.0, 2.5)};
  const RunScore s = scoreRun(frames);
  EXPECT_EQ(s.working_frames, 2);
  EXPECT_EQ(s.linear_frames, 1);
  EXPECT_NEAR(s.linear_rmse[0], 0.1, 1e-12);
  EXPECT_NEAR(s.max_error[0], 0.5, 1e-12);
}

TEST(CampaignScore, StickLabelsAreJudgedAgainstTheMarkersThatTrulyTouchAndStick) {
  // Five markers: 0-2 touch and stick, 3 touches and slips, 4 does not touch.
  ReplayFrame f = frame(0, 0);
  f.gt_contact_markers = {1, 1, 1, 1, 0};
  f.gt_slip = {0, 0, 0, 1, 0};
  f.stick = {1, 1, 0, 1, 1};  // two right, one missed, two wrong
  std::vector<ReplayFrame> frames(4, f);
  frames[3].contact = false;  // a frame the estimate does not track is not judged
  frames[3].stick = {0, 0, 0, 0, 0};
  RunScore s = scoreRun(frames);
  EXPECT_NEAR(s.stick_precision, 2.0 / 4.0, 1e-12);
  EXPECT_NEAR(s.stick_recall, 2.0 / 3.0, 1e-12);
  EXPECT_EQ(s.excess_true_stick, -1);
  // The truly sticking count is reported where a divergence starts.
  for (auto& g : frames) g.raw.dx = 2.0;
  frames[3].contact = true;
  s = scoreRun(frames);
  EXPECT_TRUE(s.diverged);
  EXPECT_EQ(s.excess_true_stick, 3);
}

TEST(CampaignScore, GrossSlipTurnSumsTheTruthsTurnWhileNoMarkerSticks) {
  std::vector<ReplayFrame> frames(6, frame(0.0, 0.0));
  const double roll[] = {0, 2, 4, 3, 6, 6};
  const ContactState state[] = {ContactState::stick, ContactState::slip, ContactState::slip, ContactState::slip,
                                ContactState::partial_slip, ContactState::slip};
  for (size_t k = 0; k < frames.size(); ++k) frames[k].gt.roll = roll[k], frames[k].gt_state = state[k];
  frames[1].gt.yaw = 1.0;  // yaw 0 -> 1 -> 0: 2 deg in all, less than the roll's
  // In gross slip: frames 1 (+2), 2 (+2), 3 (-1) and 5 (0); frame 4 (+3) is partial slip.
  EXPECT_NEAR(scoreRun(frames).gross_slip_turn_deg, 5.0, 1e-12);
}

TEST(CampaignScore, TheTurnBeforeTheDivergenceStopsAtItsFirstFrame) {
  // Roll turns 2 deg a frame in gross slip throughout; the estimate goes 1.1 mm off from frame 3 to the end.
  std::vector<ReplayFrame> frames(8, frame(0.0, 0.0));
  for (size_t k = 0; k < frames.size(); ++k) {
    frames[k].gt.roll = frames[k].raw.roll = 2.0 * static_cast<double>(k);
    frames[k].gt_state = k == 0 ? ContactState::stick : ContactState::slip;
    if (k >= 3) frames[k].raw.dx = 1.1;
  }
  RunScore s = scoreRun(frames);
  ASSERT_EQ(s.first_excess_frame, 3);
  EXPECT_NEAR(s.gross_slip_turn_deg, 14.0, 1e-12);                // frames 1..7
  EXPECT_NEAR(s.gross_slip_turn_before_excess_deg, 6.0, 1e-12);   // frames 1..3
  for (size_t k = 3; k < frames.size(); ++k) frames[k].raw.dx = 0.0;  // no excess: the whole run's
  s = scoreRun(frames);
  EXPECT_EQ(s.first_excess_frame, -1);
  EXPECT_NEAR(s.gross_slip_turn_before_excess_deg, 14.0, 1e-12);
}
