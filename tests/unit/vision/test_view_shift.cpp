// A mirror or the camera moved (vision/view_shift.hpp), on synthetic corners
// of a 17 x 17 grid with 0.02 px noise: one view translated is its mirror,
// both translated alike in the delivered frame is the camera, a change of
// disparity (the pad moving into itself) and a finger's local dimple are
// neither, noise alone moves nothing, a slow ramp is followed.
#include <gtest/gtest.h>

#include <random>

#include "vision/view_shift.hpp"

using namespace onetip;
using namespace onetip::vision;

namespace {

constexpr int kSide = 17;
constexpr double kNoisePx = 0.02;

ViewMarkers grid(double x0) {
  MarkerPattern p;
  p.rows = p.cols = kSide;
  ViewMarkers m(p);
  for (int r = 0; r < kSide; ++r)
    for (int c = 0; c < kSide; ++c) {
      m.point[static_cast<size_t>(r * kSide + c)] = cv::Point2f(static_cast<float>(x0 + 20 * c), static_cast<float>(100 + 20 * r));
      m.valid[static_cast<size_t>(r * kSide + c)] = 1;
    }
  return m;
}

// `rest` moved by `t` (view px), with noise; corners within `radius` px of `dimple` moved by 1 px more.
ViewMarkers moved(const ViewMarkers& rest, cv::Point2d t, std::mt19937& rng, cv::Point2f dimple = {-1e6, 0},
                  double radius = 0) {
  std::normal_distribution<double> n(0, kNoisePx);
  ViewMarkers m = rest;
  for (auto& p : m.point) {
    const bool pressed = cv::norm(p - dimple) < radius;
    p += cv::Point2f(static_cast<float>(t.x + n(rng) + (pressed ? 1 : 0)), static_cast<float>(t.y + n(rng)));
  }
  return m;
}

}  // namespace

TEST(ViewShift, OneViewTranslatedIsItsMirrorAndIsCorrected) {
  std::mt19937 rng(1);
  const ViewMarkers rl = grid(50), rr = grid(60);
  ViewShiftKeeper keeper(true, false);
  const ViewShiftUpdate u = keeper.update(rl, rr, moved(rl, {2, -1}, rng), moved(rr, {0, 0}, rng));
  EXPECT_TRUE(u.corrected);
  EXPECT_NE(u.report.find("left mirror"), std::string::npos) << u.report;
  EXPECT_NEAR(keeper.offset(0).x, 2, 0.01);
  EXPECT_NEAR(keeper.offset(0).y, -1, 0.01);
  EXPECT_EQ(keeper.offset(1), cv::Point2d(0, 0));
  ViewMarkers again_left = moved(rl, {2, -1}, rng), again_right = moved(rr, {0, 0}, rng);
  const ViewMarkers right_before = again_right;
  keeper.correct(again_left, again_right);
  EXPECT_NEAR(again_left.point[0].x, rl.point[0].x, 0.1);
  EXPECT_NEAR(again_left.point[0].y, rl.point[0].y, 0.1);
  EXPECT_EQ(again_right.point, right_before.point);  // the right view did not move: left as measured
}

TEST(ViewShift, BothViewsAlikeInTheDeliveredFrameIsTheCamera) {
  std::mt19937 rng(2);
  const ViewMarkers rl = grid(50), rr = grid(60);
  ViewShiftKeeper keeper(true, false);  // the left view is flipped: its x runs against the frame's
  const ViewShiftUpdate u = keeper.update(rl, rr, moved(rl, {-3, 1}, rng), moved(rr, {3, 1}, rng));
  EXPECT_TRUE(u.corrected);
  EXPECT_NE(u.report.find("the camera"), std::string::npos) << u.report;
  EXPECT_NEAR(keeper.offset(0).x, -3, 0.01);
  EXPECT_NEAR(keeper.offset(1).x, 3, 0.01);
}

TEST(ViewShift, AChangeOfDisparityIsThePadNotTheSensor) {
  std::mt19937 rng(3);
  const ViewMarkers rl = grid(50), rr = grid(60);
  ViewShiftKeeper keeper(true, false);
  // A flat plate pressing the whole pattern 0.1 mm in: the views move apart in the frame (about 3 px).
  const ViewShiftUpdate u = keeper.update(rl, rr, moved(rl, {1.5, 0}, rng), moved(rr, {1.5, 0}, rng));
  EXPECT_FALSE(u.corrected);
  EXPECT_EQ(keeper.offset(0), cv::Point2d(0, 0));
}

TEST(ViewShift, AFingersDimpleIsNotAMove) {
  std::mt19937 rng(4);
  const ViewMarkers rl = grid(50), rr = grid(60);
  ViewShiftKeeper keeper(false, false);
  // Even when the rest of the view also moved a little: the dimple's corners stay apart from the rest.
  const ViewShiftUpdate u = keeper.update(rl, rr, moved(rl, {0.5, 0}, rng, {210, 260}, 50), moved(rr, {0, 0}, rng));
  EXPECT_FALSE(u.corrected);
}

TEST(ViewShift, NoiseAloneMovesNothing) {
  std::mt19937 rng(5);
  const ViewMarkers rl = grid(50), rr = grid(60);
  ViewShiftKeeper keeper(true, false);
  for (int k = 0; k < 300; ++k) {
    const ViewShiftUpdate u = keeper.update(rl, rr, moved(rl, {0, 0}, rng), moved(rr, {0, 0}, rng));
    ASSERT_FALSE(u.corrected) << "frame " << k;
  }
}

TEST(ViewShift, ASlowRampIsFollowedAndReportedInSteps) {
  std::mt19937 rng(6);
  const ViewMarkers rl = grid(50), rr = grid(60);
  ViewShiftKeeper keeper(false, false);
  int reports = 0;
  for (int k = 1; k <= 50; ++k) {  // the right mirror drifts 5 px down over 50 frames
    const ViewShiftUpdate u = keeper.update(rl, rr, moved(rl, {0, 0}, rng), moved(rr, {0, 0.1 * k}, rng));
    if (!u.report.empty()) ++reports;
  }
  EXPECT_NEAR(keeper.offset(1).y, 5, 0.2);
  EXPECT_EQ(keeper.offset(0), cv::Point2d(0, 0));
  EXPECT_GE(reports, 8);   // every 0.5 px of correction, about
  EXPECT_LE(reports, 10);
}
