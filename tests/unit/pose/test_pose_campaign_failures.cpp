// Failure points found in the pose campaign's random runs (sim/random_scenario.hpp), replayed at field level
// with their noise: each test names the run and the frames where the estimator went wrong, and checks the
// estimate against the simulator's truth there. (test_pose_failures.cpp: the hand-made failure points.)
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "campaign_score.hpp"
#include "replay_metrics.hpp"
#include "sanitizer_leg.hpp"

using namespace onetip;
using namespace onetip::poseval;

namespace {

// Every frame from..to (indices) is in contact, truth and estimate, uses a stick model when asked, and is
// within tolerance[k] of the truth on each axis k (dx, dy, dz mm; yaw, pitch, roll deg; infinity: not judged).
void expectFollowedOver(const std::vector<ReplayFrame>& frames, size_t from, size_t to,
                        const std::array<double, 6>& tolerance, bool stick_model) {
  ASSERT_GT(frames.size(), to);
  for (size_t k = from; k <= to; ++k) {
    const ReplayFrame& f = frames[k];
    ASSERT_TRUE(f.contact && f.gt_contact) << "frame " << k;
    if (stick_model) {
      EXPECT_NE(f.model, pose::PoseModel::centroid) << "frame " << k;
    }
    const auto estimate = f.raw.asArray(), truth = f.gt.asArray();
    for (size_t a = 0; a < 6; ++a)
      EXPECT_LT(std::abs(estimate[a] - truth[a]), tolerance[a]) << "frame " << k << " axis " << a;
  }
}

constexpr double kNotJudged = std::numeric_limits<double>::infinity();

}  // namespace

TEST(FailurePoints, AFootprintDriftMustLastATimeNotTwoFrames) {
  ONETIP_PASSES_UNDER_GCC_ROUNDING_ONLY();
  // The campaign's random run 140 (foundation model, a finger on a 9x9 pattern of 2.4 mm pitch at 188 fps):
  // the finger presses to 1.33 mm, then rolls while its markers stick (to frame 194). At the end of the
  // press the footprint centre, a weighted mean over a few coarse markers, had drifted 0.22 mm off the
  // estimate; seen in two frames (11 ms) it was taken as macroscopic slip (frame 108), which froze the
  // roll the finger then began and read it as a slide (dx 1.3 mm off by frame 192). The drift must now
  // be seen for macro_confirm_s (two frames at 30 fps, 13 here). (Measured: it fails with neither change;
  // either the confirmation time or the press gate below alone keeps it, as the press was still deepening.)
  const auto frames = replayCampaignRun(140);
  int judged = 0;
  for (size_t k = 100; k < 190 && k < frames.size(); ++k) {
    const ReplayFrame& f = frames[k];
    ASSERT_TRUE(f.contact && f.gt_contact) << "frame " << k;
    if (f.gt_state != ContactState::stick) continue;
    ++judged;
    EXPECT_NE(f.model, pose::PoseModel::centroid) << "frame " << k;
    EXPECT_LT(std::abs(f.raw.dx - f.gt.dx), 0.1) << "frame " << k;
    EXPECT_LT(std::abs(f.raw.dy - f.gt.dy), 0.1) << "frame " << k;
  }
  EXPECT_GT(judged, 80);
}

TEST(FailurePoints, APressDeepeningUnderAPlateThatCoversThePadIsNotASlide) {
  ONETIP_SWEEP_RUNS_IN_RELEASE_ONLY();
  // The campaign's random run 35 (foundation model, a flat plate over a 19x19 pattern at 98 fps): at
  // frames 1114-1121 the plate presses 0.61 -> 0.74 mm deep. Its region already holds 361 markers, the
  // whole pattern, so the region-size gate cannot see the press; the footprint centre moved 0.45 mm as
  // the deformation deepened, which was confirmed as a slide (caught up, then the footprint model;
  // 0.33 mm off to the end of the contact). The footprint test makes no decision while the normal
  // deformation under it deepens by macro_size_change. (Measured: it fails without that gate, and also
  // with the gate but a two-frame confirmation.)
  const auto frames = replayCampaignRun(35);
  expectFollowedOver(frames, 1110, 1139, {0.05, 0.05, kNotJudged, kNotJudged, kNotJudged, kNotJudged}, true);
  EXPECT_FALSE(scoreRun(frames).diverged);
}

TEST(FailurePoints, AFingerPressedIntoAFoundationKeepsTheMarkersItTouches) {
  // The campaign's random run 297 (foundation model, a finger on a 21x21 pattern at 24 fps): at onset most
  // of the region is skin beside the touch, the fits follow it, and the markers under the finger, pushed
  // deeper than the estimate carries them, were all labelled detached (frame 16: 12 labelled stick, none
  // of them touching). The finger then pitched 23 deg with only skin in the stick set: the pitch froze at
  // 7.7 deg and the footprint model took over (dy 1.7 mm off by frame 54). When no marker the finger can
  // be touching sticks and at least min_thin_stick_markers of them are detached, those stick again at the
  // current estimate (pose/touching_markers.hpp): 39 of 40 labelled stick markers then truly stick.
  const auto frames = replayCampaignRun(297);
  // pitch within 1 deg (0.5-0.7 deg measured)
  expectFollowedOver(frames, 20, 60, {kNotJudged, kNotJudged, kNotJudged, kNotJudged, 1.0, kNotJudged}, true);
  EXPECT_GT(frames[60].gt.pitch, 20.0);
  EXPECT_FALSE(scoreRun(frames).diverged);
}

TEST(FailurePoints, APressIntoAFoundationIsReadByTheMarkersUnderTheCap) {
  ONETIP_SWEEP_RUNS_IN_RELEASE_ONLY();
  // The campaign's random run 132 (foundation model, a sphere on a 25x25 pattern): the first press (frames
  // 58-130, no turn) was read at 56 % of its depth. Its region grew to 90 markers, 28 of them touching; the
  // skin beside the touch, only faintly convex, was kept as touching and carried the stick fits. The cap's
  // concave core (pose/touching_markers.hpp) now picks the touch: 0.92-0.95 of the depth from frame 100.
  const auto frames = replayCampaignRun(132);
  // dz within 0.1 mm (0.07 measured; 0.35-0.55 mm before), pitch and roll within 1 deg
  expectFollowedOver(frames, 100, 124, {kNotJudged, kNotJudged, 0.1, kNotJudged, 1.0, 1.0}, false);
  EXPECT_GT(frames[100].gt.dz, 0.75);
}

TEST(FailurePoints, AtHighNoiseTheCapsCoreDoesNotHideASlide) {
  ONETIP_PASSES_UNDER_GCC_ROUNDING_ONLY();
  // slide_x at 0.012 mm of noise per axis (15x the front end's): the slip threshold (0.2 mm) is above the
  // footprint test's drift floor (0.08 mm), so the cap's concave core, the markers that stick last, creeps
  // unseen by either test; used there it held the estimate back 2 mm in gross slip with a 20 deg roll. The
  // core is only used while the slip threshold is below the drift floor. (The estimator is told the noise,
  // as the noise table does: the scenario has too few frames at rest to measure it.)
  ReplayOptions o;
  o.noise_mm = 0.012;
  o.tracker.pose.self.prior_noise_mm = o.noise_mm;
  const auto frames = replay(sampleScenario("slide_x"), o);
  EXPECT_FALSE(scoreRun(frames).diverged);
}

TEST(FailurePoints, MarkersUnderTheFingerThatStickAgainKeepTheFramesMotion) {
  // The campaign's random run 18 (foundation model, a sphere on 19x19 at 16 fps, pressed 0.35 mm a frame):
  // at frame 8 the touching markers, detached, stuck again (detachedUnderTheFinger). Anchored where they
  // were in that frame, their fit saw no motion and the frame's 0.35 mm of press was lost (dz 0.52 mm
  // short from then on). Anchored where they were a frame before, under the estimate then, they carry it.
  const auto frames = replayCampaignRun(18);
  ASSERT_GT(frames.size(), 10u);
  for (size_t k = 8; k <= 9; ++k) {
    const double true_step = frames[k].gt.dz - frames[k - 1].gt.dz;
    ASSERT_GT(true_step, 0.3) << "frame " << k;
    EXPECT_NEAR(frames[k].raw.dz - frames[k - 1].raw.dz, true_step, 0.05) << "frame " << k;
  }
}

TEST(FailurePoints, AContactBeginsWhenOneMarkerPassesTheThreshold) {
  // The campaign's random run 114 (foundation model, a 4.5 mm sphere on an 11x11 pattern of 1.92 mm pitch): the
  // sphere lands between markers and presses 0.15 mm per frame. Its nearest marker passed the 0.1 mm contact
  // threshold at frame 10, but alone above the region cut, and regions of one marker were dropped as noise:
  // the contact began at frame 13, 0.44 mm deep, and dz kept that offset (the truth starts at the threshold,
  // docs/reference.md). Now the contact begins at frame 10 and the press is followed from there.
  const auto frames = replayCampaignRun(114);
  expectFollowedOver(frames, 10, 21, {0.02, 0.02, 0.02, 0.2, 0.2, 0.2}, false);
}

TEST(FailurePoints, APressOnASmallContactFollowsTheMarkersTheFingerTouches) {
  ONETIP_PASSES_UNDER_GCC_ROUNDING_ONLY();
  // The campaign's random run 89 (foundation model, l = 4.3 mm, a finger on an 11x11 pattern at 48 fps):
  // the finger presses 1.11 mm from frame 20 to 33 and holds while its markers stick. The region is 12-20
  // markers, of which 4-12 are touched; the rest is skin beside the touch, dipping about half as much. The
  // trimmed stick fit followed that majority and dropped the four touched markers: the press was read
  // 0.28 mm short, for good (the anchors of markers joining later carried the short estimate). The cap's
  // markers (touching_markers.hpp's capMarkers) now carry the fit whenever the trim would drop most of them.
  // (Measured: without the cap the press is read short from its first frames, by 0.28 mm once it holds.)
  const auto frames = replayCampaignRun(89);
  expectFollowedOver(frames, 21, 45, {0.01, 0.01, 0.01, 0.2, 0.2, 0.2}, true);
}

TEST(FailurePoints, TwoFingersWhoseImprintsJoinAreTrackedApart) {
  // The campaign's random run 38 (half-space model, two fingers on a 19x19 pattern at 44 fps): the tracked
  // finger pitches back from 29 deg while the second one, 6-7 mm away, moves on its own. At frame 224 the
  // deformation between them passed the region cut and the two imprints became one region; its stick set
  // then held both fingers' markers, and the estimate followed a mixture (pitch 3.7 deg off by frame 232,
  // 16 deg by frame 272). The contact stage now splits a region at a valley between two peaks
  // (contact/finger_valleys.hpp): the two stay apart and the tracked one is followed through the pitch.
  // (Measured: it fails without the split, from frame 226.)
  const auto frames = replayCampaignRun(38);
  expectFollowedOver(frames, 220, 340, {0.05, 0.05, 0.05, 1.0, 1.0, 1.0}, true);
  EXPECT_GT(frames[220].gt.pitch - frames[340].gt.pitch, 30.0);
}

TEST(FailurePoints, AFingerLiftingBesideAnotherEndsItsContactWhenItStopsTouching) {
  // The campaign's random run 60 (half-space, two spheres on 19x19 at 15 fps): twice a tracked sphere lifts while
  // the other stays. Under one global cut (40 % of the deeper imprint) the lifting sphere's region vanished a frame
  // before it stopped touching, so the estimate's new contact began a frame before the truth's (frames 63 and 79
  // instead of 64 and 80). It counted that frame's motion of the other sphere, which the truth does not: the
  // second contact ran 1.0 deg of yaw and roll off to its end, and the first handover frame was 28 deg off in
  // pitch. Cut at 40 % of its own peak, a finger's region lasts until its imprint falls below the contact
  // threshold, here the frame the truth's contact ends. (Measured: it fails with one cut.)
  const auto frames = replayCampaignRun(60);
  int handovers = 0;
  for (size_t k = 1; k < frames.size(); ++k) {
    const auto& ev = frames[k].events;
    if (!frames[k - 1].contact || std::count(ev.begin(), ev.end(), input::EventType::contact_begin) == 0) continue;
    ++handovers;
    // The truth begins its new contact in the same frame: its 6-D input is zero there.
    for (double v : frames[k].gt.asArray()) EXPECT_NEAR(v, 0.0, 1e-9) << "frame " << k;
  }
  EXPECT_EQ(handovers, 2);
  expectFollowedOver(frames, 81, 100, {0.05, 0.05, 0.05, 0.3, 0.3, 0.3}, true);
}
