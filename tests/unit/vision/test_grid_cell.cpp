// The cell test of the grid tracker's rescue (cellMargin, vision/grid_checks.hpp)
// on exact lattices, and the rescue it feeds on a synthetic stick-slip edge:
// - under any affine map of the lattice a marker's own corner sits at margin 1,
//   a 4-neighbour's corner at 0 and a diagonal neighbour's at -1, also in the
//   open cell of a marker on the pattern's border;
// - no answer where an inner neighbour is missing (its corner may lie on that
//   side) or the cell is not convex;
// - a marker off its neighbours' motion at a stick-slip edge (half its
//   neighbours stuck, half jumped) is kept, in its place, with confidence 0.5,
//   and is dropped without the rescue; a corner 0.45 of a square off where its
//   neighbours' motion puts it, further than the near-swap bound of 0.4, is
//   dropped even inside its cell (ACornerOffItsPlace... in test_fast_motion.cpp);
// - the pair's cell (pairCellMargins): the hexagon of two neighbours' six
//   neighbours holds their two corners alone (2/3 each, every other corner at
//   or below 0), the right way round; two neighbours off together are kept;
// - the rescue's three models (rescueOffMotion, grid_rescue.hpp): a marker
//   half a square off its neighbours' motion is kept where their spatial
//   completion or its own track puts it, dropped 0.45 of a square off all
//   three; in the tracker, a marker sliding on while its neighbours stand
//   still is kept in its place by its own track (predictFromOwnTrack; the
//   test fails without that model); lost for one frame half a square off
//   its neighbours' spatial completion, it is carried by their motion and
//   found again in its place (fails when the lost marker is completed
//   spatially instead).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>

#include "synthetic_board.hpp"
#include "vision/grid_checks.hpp"
#include "vision/grid_rescue.hpp"
#include "vision/grid_tracker.hpp"

namespace onetip::vision {
namespace {

struct Lattice {
  int rows, cols;
  std::vector<cv::Point2f> point;
  std::vector<std::uint8_t> valid;
  LatticeView view() const { return {rows, cols, &point, &valid}; }
};

// (r, c) -> A (c, r) + t: rotation 25 deg, shear 0.3, scales 40 and 25 px.
cv::Point2f affine(double r, double c) {
  const double a = 25 * M_PI / 180, sx = 40, sy = 25, shear = 0.3;
  const double u = sx * (c + shear * r), v = sy * r;
  return {static_cast<float>(std::cos(a) * u - std::sin(a) * v + 300), static_cast<float>(std::sin(a) * u + std::cos(a) * v + 200)};
}

Lattice affineLattice(int rows, int cols) {
  Lattice l{rows, cols, {}, {}};
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) l.point.push_back(affine(r, c)), l.valid.push_back(1);
  return l;
}

TEST(GridCell, MarginIsAffineInvariantOwnCornerOneNeighbourZeroDiagonalMinusOne) {
  const Lattice l = affineLattice(5, 5);
  EXPECT_NEAR(*cellMargin(l.view(), 2, 2, affine(2, 2)), 1.0f, 1e-4f);
  for (const auto& [dr, dc] : {std::pair{0, 1}, {1, 0}, {0, -1}, {-1, 0}})
    EXPECT_NEAR(*cellMargin(l.view(), 2, 2, affine(2 + dr, 2 + dc)), 0.0f, 1e-4f);
  for (const auto& [dr, dc] : {std::pair{1, 1}, {1, -1}, {-1, 1}, {-1, -1}})
    EXPECT_NEAR(*cellMargin(l.view(), 2, 2, affine(2 + dr, 2 + dc)), -1.0f, 1e-4f);
  EXPECT_NEAR(*cellMargin(l.view(), 2, 2, affine(2, 2.3)), 0.7f, 1e-4f);  // 0.3 of a square towards a neighbour
}

TEST(GridCell, BorderCellIsOpenBeyondThePattern) {
  const Lattice l = affineLattice(5, 5);
  // Row 0: no up neighbour, the cell is the wedge left, down, right.
  EXPECT_NEAR(*cellMargin(l.view(), 0, 2, affine(0, 2)), 1.0f, 1e-4f);
  EXPECT_NEAR(*cellMargin(l.view(), 0, 2, affine(1, 3)), -1.0f, 1e-4f);
  EXPECT_NEAR(*cellMargin(l.view(), 0, 2, affine(1, 1)), -1.0f, 1e-4f);
  EXPECT_LT(*cellMargin(l.view(), 0, 2, affine(0, 4)), -0.9f);  // two along the border
  EXPECT_GT(*cellMargin(l.view(), 0, 2, affine(-0.5, 2)), 1.0f - 1e-4f);  // beyond the border: no corner there
  // A corner of the pattern has two neighbours only: no cell.
  EXPECT_FALSE(cellMargin(l.view(), 0, 0, affine(0, 0)).has_value());
}

TEST(GridCell, NoAnswerWithAnInnerNeighbourMissingOrACellNotConvex) {
  Lattice l = affineLattice(5, 5);
  l.valid[static_cast<size_t>(2 * 5 + 3)] = 0;  // right neighbour of (2, 2) not measured
  EXPECT_FALSE(cellMargin(l.view(), 2, 2, affine(2, 2)).has_value());
  l = affineLattice(5, 5);
  l.point[static_cast<size_t>(1 * 5 + 2)] = affine(2.3, 2);  // up neighbour folded past the centre
  EXPECT_FALSE(cellMargin(l.view(), 2, 2, affine(2, 2)).has_value());
}

TEST(GridCell, PairCellHoldsTheTwoCornersAloneTheRightWayRound) {
  Lattice l = affineLattice(6, 6);
  // (2, 2) and (2, 3), neither a vertex of the other's cell: their hexagon.
  l.valid[static_cast<size_t>(2 * 6 + 2)] = l.valid[static_cast<size_t>(2 * 6 + 3)] = 0;
  const auto m = pairCellMargins(l.view(), 2, 2, 0, 1, affine(2, 2), affine(2, 3));
  ASSERT_TRUE(m.has_value());
  EXPECT_NEAR(m->first, 2.0f / 3.0f, 1e-4f);
  EXPECT_NEAR(m->second, 2.0f / 3.0f, 1e-4f);
  EXPECT_FALSE(pairCellMargins(l.view(), 2, 2, 0, 1, affine(2, 3), affine(2, 2)).has_value());  // swapped
  // Every other corner is on or beyond the hexagon (the second point far along
  // the pair's axis keeps the order test out of the way).
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) {
      if (r == 2 && (c == 2 || c == 3)) continue;
      const auto other = pairCellMargins(l.view(), 2, 2, 0, 1, affine(r, c), affine(2, 20));
      ASSERT_TRUE(other.has_value()) << r << " " << c;
      EXPECT_LE(other->first, 1e-4f) << r << " " << c;
    }
  // Down the columns, and open on the pattern's border: (2, 5) and (3, 5).
  l = affineLattice(6, 6);
  l.valid[static_cast<size_t>(2 * 6 + 5)] = l.valid[static_cast<size_t>(3 * 6 + 5)] = 0;
  const auto border = pairCellMargins(l.view(), 2, 5, 1, 0, affine(2, 5), affine(3, 5));
  ASSERT_TRUE(border.has_value());
  EXPECT_NEAR(border->first, 2.0f / 3.0f, 1e-4f);
  EXPECT_NEAR(border->second, 2.0f / 3.0f, 1e-4f);
}

// A 7 x 7 lattice of 30 px squares turned by 20 deg, (3, 3) at `centre`
// (lattice units) and rejected as 0.5 of a square off its neighbours' motion,
// its own track putting it at `track_squares` from there; whether the rescue
// keeps it.
bool rescued(cv::Point2f centre, float track_squares) {
  const MarkerPattern pattern{7, 7, 1.0};
  const auto at = [](float r, float c) {
    const float a = 20.0f * static_cast<float>(M_PI) / 180.0f, s = 30.0f;
    return cv::Point2f(s * (std::cos(a) * c - std::sin(a) * r) + 200, s * (std::sin(a) * c + std::cos(a) * r) + 200);
  };
  ViewMarkers m(pattern);
  for (int r = 0; r < 7; ++r)
    for (int c = 0; c < 7; ++c) m.set(pattern.id(r, c), at(static_cast<float>(r), static_cast<float>(c)));
  const int id = pattern.id(3, 3);
  const ViewMarkers before = m;
  m.set(id, at(centre.y, centre.x));
  std::vector<int> reject{id};
  std::vector<float> confidence(static_cast<size_t>(pattern.count()), 1.0f), spacing(confidence.size(), 30.0f);
  rescueOffMotion(pattern, m, LatticeView{7, 7, &before.point, &before.valid}, spacing, {{id, 0.5f, track_squares}},
                  RescueLimits{0.15f, 2.0f}, reject, confidence);
  return reject.empty();
}

TEST(GridRescue, KeptWhereOneModelOfTheFieldPutsItDroppedOffAllThree) {
  EXPECT_TRUE(rescued({3, 3}, kNoTrack));             // where the neighbours complete it
  EXPECT_FALSE(rescued({3.45f, 3}, kNoTrack));        // 0.45 of a square off their completion and motion
  EXPECT_TRUE(rescued({3.45f, 3}, 0.1f));             // ... but where its own track puts it
  EXPECT_FALSE(rescued({3.45f, 3}, 0.45f));           // off all three
  // On its own track but 0.55 of a square towards its right neighbour: still inside its cell (margin
  // 0.45), dropped because that link shrinks 2.2x in one frame (beyond max_link_stretch 2). At 0.45 of a
  // square the same marker would be kept: a corner that far off which its own track vouches for passes.
  EXPECT_FALSE(rescued({3.0f, 3.55f}, 0.0f));
}

const MarkerPattern kPattern{17, 17, 1.2};
const cv::Size kView(960, 1080);

// The next frame's corners: columns right of `edge_col` jumped `jump` squares
// along x, column edge_col moved `own` squares, the rest stood still.
// `own_rows` of column edge_col moved `own` squares, the rest of it stood still.
std::vector<Corner> stickSlipFrame(const GridTracker& tracker, const std::vector<Corner>& rest, int edge_col, float jump,
                                   float own, float square_px, std::vector<int> own_rows = {8}) {
  std::vector<Corner> next = rest;
  for (Corner& c : next) {
    for (int id = 0; id < kPattern.count(); ++id) {
      if (cv::norm(c.pt - tracker.rest().point[static_cast<size_t>(id)]) > 1.0) continue;
      const int col = kPattern.colOf(id), row = kPattern.rowOf(id);
      if (col > edge_col) c.pt.x += jump * square_px;
      if (col == edge_col && std::find(own_rows.begin(), own_rows.end(), row) != own_rows.end()) c.pt.x += own * square_px;
    }
  }
  return next;
}

// A rest board (17 x 17, 40 px squares) and its detected corners.
class GridCellTracking : public ::testing::Test {
 protected:
  const cv::Mat img = testing::renderBoard(testing::BoardWarp{}, testing::BoardLook{}, kView);
  const ViewHalf view{img, false};
  const CornerDetector detector;
  const std::vector<Corner> rest = detectInView(detector, view);
};

TEST_F(GridCellTracking, AMarkerAtAStickSlipEdgeIsKeptInItsPlace) {
  const int id = kPattern.id(8, 8);
  // (8, 8) moved 0.34 of a square, its right-hand neighbours 0.35, its left-hand
  // ones and the rest of its column not at all: off the neighbours' motion
  // (their median: none) by more than the tolerance, 0.3 of the local spacing.
  for (const float rescue : {0.15f, 0.0f}) {
    GridTrackerOptions options;
    options.rescue_fraction = rescue;
    GridTracker tracker(kPattern, options);
    ASSERT_TRUE(tracker.initialize(view, detector).ok());
    const cv::Point2f truth = tracker.rest().point[static_cast<size_t>(id)] + cv::Point2f(0.34f * 40, 0);
    const GridResult r = tracker.track(stickSlipFrame(tracker, rest, 8, 0.35f, 0.34f, 40), view);
    ASSERT_TRUE(r.ok()) << r.message;
    if (rescue > 0) {
      ASSERT_TRUE(r.markers.valid[static_cast<size_t>(id)]);
      EXPECT_LT(cv::norm(r.markers.point[static_cast<size_t>(id)] - truth), 0.01);
      EXPECT_FLOAT_EQ(r.markers.confidence[static_cast<size_t>(id)], 0.5f);
    } else {
      EXPECT_FALSE(r.markers.valid[static_cast<size_t>(id)]) << "the case must need the rescue";
    }
  }
}

TEST_F(GridCellTracking, TwoNeighboursOffTogetherAreKeptAsAPair) {
  // (8, 8) and (9, 8) both moved 0.38 of a square, everything else stood
  // still: each is off its neighbours' motion by more than the tolerance, lacks
  // the other as a vertex of its own cell, and lies 0.37 of a square from the
  // completions by its passing neighbours.
  GridTracker tracker(kPattern);
  ASSERT_TRUE(tracker.initialize(view, detector).ok());
  const GridResult r = tracker.track(stickSlipFrame(tracker, rest, 8, 0.0f, 0.38f, 40, {8, 9}), view);
  ASSERT_TRUE(r.ok()) << r.message;
  for (const int row : {8, 9}) {
    const size_t id = static_cast<size_t>(kPattern.id(row, 8));
    ASSERT_TRUE(r.markers.valid[id]) << row;
    EXPECT_LT(cv::norm(r.markers.point[id] - (tracker.rest().point[id] + cv::Point2f(0.38f * 40, 0))), 0.01) << row;
    EXPECT_FLOAT_EQ(r.markers.confidence[id], 0.5f) << row;
  }
}

TEST_F(GridCellTracking, AMarkerSlidingOnPastNeighboursThatStandStillIsFoundAndKept) {
  // (8, 8) moves 0.1 of a square along x, then 0.42 more, every other marker
  // stands still: in the second frame its neighbours' motion puts it 0.42 of
  // a square behind its corner, beyond the search radius (0.4) and the
  // near-swap bound, its own track (last + its motion) 0.32 of a square (its
  // link to the right shrinks 1.9x, inside the 2x a link may change).
  GridTracker tracker(kPattern);
  ASSERT_TRUE(tracker.initialize(view, detector).ok());
  const size_t id = static_cast<size_t>(kPattern.id(8, 8));
  ASSERT_TRUE(tracker.track(stickSlipFrame(tracker, rest, 8, 0.0f, 0.1f, 40), view).markers.valid[id]);
  const GridResult r = tracker.track(stickSlipFrame(tracker, rest, 8, 0.0f, 0.52f, 40), view);
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_TRUE(r.markers.valid[id]);
  EXPECT_LT(cv::norm(r.markers.point[id] - (tracker.rest().point[id] + cv::Point2f(0.52f * 40, 0))), 0.01);
  EXPECT_FLOAT_EQ(r.markers.confidence[id], 0.5f);
  EXPECT_EQ(r.found, kPattern.count());
}

TEST_F(GridCellTracking, AMarkerLostForAFrameIsCarriedByItsNeighboursMotionAndFoundAgainInItsPlace) {
  // (8, 8) slides 0.25 then 0.25 more of a square along x while the rest
  // stands still (kept by its own track), is not detected in the third frame,
  // and in the fourth the whole board has moved 0.2 of a square along y: its
  // neighbours' spatial completion is then half a square off its corner (a
  // near-swap for the rescue), its place among them carried through the lost
  // frame by their motion is on it.
  GridTracker tracker(kPattern);
  ASSERT_TRUE(tracker.initialize(view, detector).ok());
  const size_t id = static_cast<size_t>(kPattern.id(8, 8));
  const cv::Point2f slid = tracker.rest().point[id] + cv::Point2f(0.5f * 40, 0);
  ASSERT_TRUE(tracker.track(stickSlipFrame(tracker, rest, 8, 0.0f, 0.25f, 40), view).markers.valid[id]);
  std::vector<Corner> frame = stickSlipFrame(tracker, rest, 8, 0.0f, 0.5f, 40);
  ASSERT_TRUE(tracker.track(frame, view).markers.valid[id]);
  std::vector<Corner> hidden;
  std::copy_if(frame.begin(), frame.end(), std::back_inserter(hidden),
               [&](const Corner& c) { return cv::norm(c.pt - slid) > 1.0; });
  ASSERT_EQ(hidden.size() + 1, frame.size());
  const GridResult lost = tracker.track(hidden, view);
  ASSERT_TRUE(lost.ok()) << lost.message;
  EXPECT_FALSE(lost.markers.valid[id]);
  EXPECT_EQ(lost.found, kPattern.count() - 1);
  for (Corner& c : frame) c.pt.y += 0.2f * 40;
  const GridResult r = tracker.track(frame, view);
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_TRUE(r.markers.valid[id]);
  EXPECT_LT(cv::norm(r.markers.point[id] - (slid + cv::Point2f(0, 0.2f * 40))), 0.01);
  EXPECT_EQ(r.found, kPattern.count());
}

}  // namespace
}  // namespace onetip::vision
