// The grid tracker under the motions that broke it before issue 16, rendered
// by the simulator and scored against its exact truth (the campaign's own
// runs and scoring, tests/bench/vision/campaign_*.hpp): a fast slide with
// two reversals at half a square per frame, and a slide reversal after heavy
// shear (2 mm press, friction 2) on the 25x25 pattern with blur. In-contact
// markers are those touching the finger; a gross error is a marker reported
// more than 0.4 of a square from its truth (a swap or a near-swap).
// Also, on exact synthetic boards: a corner detected off its place is
// dropped for that frame, never reported at a neighbour's position, and the
// tracker's confidence reaches the triangulated field.
#include <gtest/gtest.h>

#include <cstdio>

#include "campaign_score.hpp"
#include "synthetic_board.hpp"
#include "vision/grid_tracker.hpp"
#include "vision/triangulator.hpp"
#include "sanitizer_leg.hpp"

namespace onetip::vision {
namespace {

struct Totals {
  long contact = 0, found = 0, gross = 0;
  double worst = 1;  // over frames with at least 10 in-contact markers
};

Totals play(const bench::CampaignRun& run) {
  Totals t;
  for (const bench::FrameScore& f : bench::playRun(run)) {
    t.contact += f.contact, t.found += f.contact_found, t.gross += f.gross;
    if (f.contact >= 10) t.worst = std::min(t.worst, static_cast<double>(f.contact_found) / f.contact);
  }
  std::printf("%s %dx%d at %.2f squares/frame: in contact %ld/%ld (%.2f%%), worst frame %.1f%%, gross %ld\n", run.kind.c_str(),
              run.scenario.pad.pattern.rows, run.scenario.pad.pattern.cols, run.speed_sq, t.found, t.contact,
              100.0 * t.found / std::max(t.contact, 1L), 100 * t.worst, t.gross);
  return t;
}

TEST(FastMotion, SlideWithReversalsAtHalfASquarePerFrameLosesAndSwapsNothing) {
  ONETIP_SWEEP_RUNS_IN_RELEASE_ONLY();
  // 17x17, noise 6, no blur (run index 17 of the campaign's conditions).
  const Totals t = play(bench::slideRun(17, 0.5, false));
  EXPECT_EQ(t.gross, 0);
  EXPECT_GE(t.found, 0.995 * t.contact);
  EXPECT_GE(t.worst, 0.98);
}

TEST(FastMotion, ReversalAfterHeavyShearOnTheFinestPatternSwapsNothing) {
  ONETIP_SWEEP_RUNS_IN_RELEASE_ONLY();
  // 25x25 (0.8 mm squares), noise 3, blur 1.2 px (run index 14).
  const Totals t = play(bench::shearRun(14, 0.4));
  EXPECT_EQ(t.gross, 0);
  EXPECT_GE(t.found, 0.97 * t.contact);  // measured 97.9 %: the deepest-pressed corners defeat the detector
}

const MarkerPattern kPattern{17, 17, 1.2};
const cv::Size kView(960, 1080);

TEST(FastMotion, ACornerOffItsPlaceIsDroppedNotReportedAndConfidenceReachesTheField) {
  const testing::BoardWarp warp;
  testing::BoardLook look;
  const cv::Mat img = testing::renderBoard(warp, look, kView);
  const ViewHalf view{img, false};
  const CornerDetector detector;
  GridTracker tracker(kPattern);
  ASSERT_TRUE(tracker.initialize(view, detector).ok());
  // The next frame: every corner where it was, except the corner of (8, 8),
  // detected 0.45 of a square towards its right neighbour.
  std::vector<Corner> corners = detectInView(detector, view);
  const cv::Point2f moved = tracker.rest().point[static_cast<size_t>(kPattern.id(8, 8))];
  for (Corner& c : corners)
    if (cv::norm(c.pt - moved) < 1.0) c.pt.x += static_cast<float>(0.45 * warp.square_px);
  const GridResult r = tracker.track(corners, view);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_FALSE(r.markers.valid[static_cast<size_t>(kPattern.id(8, 8))]);
  EXPECT_TRUE(r.markers.valid[static_cast<size_t>(kPattern.id(8, 9))]);
  EXPECT_EQ(r.found, kPattern.count() - 1);
  for (int id = 0; id < kPattern.count(); ++id) {
    if (r.markers.valid[static_cast<size_t>(id)]) {
      EXPECT_GT(r.markers.confidence[static_cast<size_t>(id)], 0.9f) << id;
    }
  }

  // The triangulated field carries the lower of the two views' confidences.
  StereoCalibration calib;
  calib.image_width = 2 * kView.width, calib.image_height = kView.height, calib.split_x = kView.width;
  calib.K_left = calib.K_right = cv::Matx33d(1000, 0, 480, 0, 1000, 540, 0, 0, 1);
  calib.T = cv::Vec3d(-24, 0, 0);
  ViewMarkers left = r.markers, right = r.markers;
  for (cv::Point2f& p : right.point) p.x -= 40;  // a plane in front of both cameras
  left.confidence[0] = 0.3f, right.confidence[0] = 0.6f, right.confidence[1] = 0.2f;
  const TriangulationResult tri = Triangulator(calib).triangulate(left, right);
  ASSERT_TRUE(tri.markers.valid[0] && tri.markers.valid[1]);
  EXPECT_FLOAT_EQ(tri.markers.confidence[0], 0.3f);
  EXPECT_FLOAT_EQ(tri.markers.confidence[1], 0.2f);
}

}  // namespace
}  // namespace onetip::vision
