// Grid tracker against exact synthetic ground truth (synthetic_board.hpp):
// ids anchored per docs/reference.md, no id swaps over a sequence of growing
// deformation, visible markers keep their ids with 20% of the pad occluded,
// lost markers recovered, flipped views, bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "synthetic_board.hpp"
#include "vision/grid_tracker.hpp"

namespace onetip::vision {
namespace {

using testing::BoardLook;
using testing::BoardWarp;

const cv::Size kView(960, 1080);
const MarkerPattern kPattern{17, 17, 1.2};

struct IdCheck {
  int visible = 0, found = 0, swapped = 0;
};

// Every measured id must sit on its own ground-truth corner (within 0.5 px;
// the next corner is a whole square away); counts the visible ones found.
IdCheck checkIds(const ViewMarkers& m, const std::vector<testing::GroundTruthCorner>& truth) {
  IdCheck c;
  for (const auto& t : truth) {
    const int id = kPattern.id(t.row, t.col);
    const bool valid = m.valid[static_cast<size_t>(id)];
    if (t.visible) ++c.visible;
    if (!valid) continue;
    const cv::Point2d d = cv::Point2d(m.point[static_cast<size_t>(id)]) - t.pixel;
    if (std::sqrt(d.dot(d)) > 0.5) ++c.swapped;
    else if (t.visible) ++c.found;
  }
  return c;
}

BoardLook noisyLook(std::uint64_t seed) {
  BoardLook look;
  look.blur_sigma = 1.0, look.noise_sigma = 2.0, look.light_ramp = 0.4, look.seed = seed;
  return look;
}

// Frame k of a sequence growing from rest to the largest deformation.
BoardWarp sequenceWarp(int k, int frames) {
  const double t = static_cast<double>(k) / frames;
  BoardWarp w;
  w.bulge = 0.667 * t;  // local scale down to 0.6x at the centre
  w.rotation_deg = 12 * t;
  w.shear = 0.15 * t;
  w.offset = {0.3 * t, -0.2 * t};  // the pad slides by a fraction of a square
  return w;
}

TEST(GridTracker, RestFrameIdsAnchoredTopLeft) {
  const BoardWarp w;
  const BoardLook look = noisyLook(7);
  const cv::Mat img = testing::renderBoard(w, look, kView);
  GridTracker tracker(kPattern);
  const GridResult r = tracker.initialize(ViewHalf{img, false}, CornerDetector());
  ASSERT_TRUE(r.ok()) << r.message;
  const IdCheck c = checkIds(r.markers, testing::groundTruthCorners(w, look, kView));
  EXPECT_EQ(c.found, kPattern.count());
  EXPECT_EQ(c.swapped, 0);
}

TEST(GridTracker, GrowingDeformationNoIdSwaps) {
  constexpr int kFrames = 8;
  const CornerDetector detector;
  GridTracker full(kPattern), local(kPattern);  // full-image detection vs local search
  for (int k = 0; k <= kFrames; ++k) {
    const BoardWarp w = sequenceWarp(k, kFrames);
    const BoardLook look = noisyLook(100 + static_cast<std::uint64_t>(k));
    const cv::Mat img = testing::renderBoard(w, look, kView);
    const auto truth = testing::groundTruthCorners(w, look, kView);
    const ViewHalf view{img, false};
    GridResult a, b;
    if (k == 0) {
      a = full.initialize(view, detector);
      b = local.initialize(view, detector);
    } else {
      a = full.track(detectInView(detector, view), view);
      b = local.track(view, detector);
    }
    ASSERT_TRUE(a.ok() && b.ok()) << "frame " << k << ": " << a.message << b.message;
    for (const GridResult* r : {&a, &b}) {
      const IdCheck c = checkIds(r->markers, truth);
      EXPECT_EQ(c.swapped, 0) << "frame " << k;
      EXPECT_GE(c.found, 0.995 * c.visible) << "frame " << k;
      if (k == kFrames) std::printf("largest deformation: %d/%d found, %d swapped, %d rejected\n", c.found, c.visible, c.swapped, r->rejected);
    }
  }
}

TEST(GridTracker, OccludedPadKeepsIdsAndRecovers) {
  const CornerDetector detector;
  GridTracker tracker(kPattern);
  BoardWarp w;
  BoardLook look = noisyLook(5);
  ASSERT_TRUE(tracker.initialize(ViewHalf{testing::renderBoard(w, look, kView), false}, detector).ok());
  // A band over 20% of the board (18 x 18 squares), through its middle.
  look.occluder = cv::Rect2d(-1.0, -9.0, 3.6, 18.0);
  for (int k = 1; k <= 4; ++k) {
    w.bulge = 0.1 * k, w.offset = {0.05 * k, 0.05 * k};
    look.seed = 20 + static_cast<std::uint64_t>(k);
    const GridResult r = tracker.track(ViewHalf{testing::renderBoard(w, look, kView), false}, detector);
    ASSERT_TRUE(r.ok()) << r.message;
    const IdCheck c = checkIds(r.markers, testing::groundTruthCorners(w, look, kView));
    EXPECT_EQ(c.swapped, 0) << "frame " << k;
    EXPECT_GE(c.found, 0.995 * c.visible) << "frame " << k;
    for (const auto& t : testing::groundTruthCorners(w, look, kView)) {  // nothing invented under the band
      const cv::Point2d uv(t.col - 8.0, t.row - 8.0);
      const bool under = uv.x > look.occluder.x && uv.x < look.occluder.br().x;
      EXPECT_FALSE(under && r.markers.valid[static_cast<size_t>(kPattern.id(t.row, t.col))]) << "frame " << k;
    }
  }
  look.occluder = {};  // uncovered: every marker comes back, on its own corner
  look.seed = 99;
  const GridResult r = tracker.track(ViewHalf{testing::renderBoard(w, look, kView), false}, detector);
  const IdCheck c = checkIds(r.markers, testing::groundTruthCorners(w, look, kView));
  EXPECT_EQ(c.swapped, 0);
  EXPECT_EQ(c.found, kPattern.count());
  EXPECT_GT(r.recovered, 0);
}

TEST(GridTracker, FlippedViewGivesTheSameIds) {
  const BoardWarp w;
  const BoardLook look = noisyLook(3);
  const cv::Mat img = testing::renderBoard(w, look, kView);
  cv::Mat mirrored;
  cv::flip(img, mirrored, 1);
  const GridResult direct = detectBoard(ViewHalf{img, false}, kPattern);
  const GridResult flipped = detectBoard(ViewHalf{mirrored, true}, kPattern);
  ASSERT_TRUE(direct.ok() && flipped.ok());
  for (int id = 0; id < kPattern.count(); ++id) {
    ASSERT_TRUE(flipped.markers.valid[static_cast<size_t>(id)]);
    const cv::Point2f d = flipped.markers.point[static_cast<size_t>(id)] - direct.markers.point[static_cast<size_t>(id)];
    EXPECT_LT(std::sqrt(d.dot(d)), 0.01f) << "id " << id;
  }
}

TEST(GridTracker, BlankFrameIsLostThenTrackingResumes) {
  const CornerDetector detector;
  GridTracker tracker(kPattern);
  const BoardWarp w;
  const BoardLook look = noisyLook(11);
  const cv::Mat img = testing::renderBoard(w, look, kView);
  ASSERT_TRUE(tracker.initialize(ViewHalf{img, false}, detector).ok());
  const cv::Mat blank(kView, CV_8UC1, cv::Scalar::all(128));
  EXPECT_EQ(tracker.track(ViewHalf{blank, false}, detector).status, GridStatus::Lost);
  EXPECT_EQ(tracker.track(detectInView(detector, ViewHalf{blank, false}), ViewHalf{blank, false}).status, GridStatus::Lost);
  const GridResult again = tracker.track(ViewHalf{img, false}, detector);
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(checkIds(again.markers, testing::groundTruthCorners(w, look, kView)).found, kPattern.count());
}

TEST(GridTracker, BadInputAndIncompleteGrids) {
  GridTracker tracker(kPattern);
  const cv::Mat grey(kView, CV_8UC1, cv::Scalar::all(128));
  EXPECT_EQ(tracker.track(std::vector<Corner>{}, ViewHalf{grey, false}).status, GridStatus::NotInitialized);
  const cv::Mat blank(kView, CV_8UC1, cv::Scalar::all(128));
  EXPECT_EQ(tracker.initialize(std::vector<Corner>{}, ViewHalf{blank, false}).status, GridStatus::GridNotFound);
  EXPECT_THROW(tracker.initialize(std::vector<Corner>{}, ViewHalf{cv::Mat(), false}), InputError);
  EXPECT_EQ(tracker.track(ViewHalf{blank, false}, CornerDetector()).status, GridStatus::NotInitialized);
  // The board partly outside the view: ids would be ambiguous.
  BoardWarp w;
  w.cx = 150;
  const cv::Mat cut = testing::renderBoard(w, noisyLook(2), kView);
  const GridResult r = detectBoard(cut, kPattern);
  EXPECT_EQ(r.status, GridStatus::GridIncomplete) << r.message;
  EXPECT_FALSE(tracker.initialize(ViewHalf{cut, false}, CornerDetector()).ok());
  EXPECT_FALSE(tracker.initialized());
  // A frame of the wrong type after a good start.
  ASSERT_TRUE(tracker.initialize(ViewHalf{testing::renderBoard(BoardWarp{}, noisyLook(4), kView), false}, CornerDetector()).ok());
  EXPECT_THROW(tracker.track(ViewHalf{cv::Mat(), false}, CornerDetector()), InputError);
  EXPECT_THROW(detectBoard(cv::Mat(), kPattern), InputError);
  EXPECT_THROW(detectBoard(cv::Mat(10, 10, CV_8UC3), kPattern), InputError);
  GridTrackerOptions bad;
  bad.search_radius = 0.7f;
  EXPECT_THROW(GridTracker(kPattern, bad), InputError);
  EXPECT_THROW(GridTracker(MarkerPattern{0, 17, 1.2}), InputError);
}

}  // namespace
}  // namespace onetip::vision
