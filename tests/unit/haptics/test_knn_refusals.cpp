// What the kNN renderer cannot answer: a query with a NaN or infinite value
// (or one that overflows the float search space) has no neighbour, and the
// result must say so (empty neighbour list, NaN command that a device refuses)
// instead of handing back the previous query's rows or row 0 of a zeroed
// buffer; and the bounds a live sensed vector must pass before it is rendered.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "haptics/kd_tree_index.hpp"
#include "haptics/knn_renderer.hpp"
#include "haptics/sensed_bounds.hpp"

using namespace onetip::haptics;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// 500 rows of 4 channels around 1000 counts (sd 20), commands spread over the
// platform's range, row 0's command far from the others' mean.
TactileDataset countsDataset() {
  std::mt19937 rng(3);
  std::normal_distribution<double> n01;
  TactileDataset d;
  d.channels = 4;
  for (int r = 0; r < 500; ++r) {
    std::vector<double> s(4);
    for (double& v : s) v = 1000.0 + 20.0 * n01(rng);
    d.append({30.0 + r % 50 * 3.0, 60.0 + r % 7 * 10.0, 190.0 - r % 11 * 5.0}, s);
  }
  return d;
}

}  // namespace

TEST(KdTree, QueryWithoutAFiniteDistanceFindsNoNeighbourAndClearsTheResult) {
  std::vector<float> points;
  for (int i = 0; i < 200; ++i) points.insert(points.end(), {float(i % 10), float(i / 10), float(i % 7)});
  const KdTreeIndex tree(points, 3, KdTreeOptions{4});
  const float finite[3] = {2.5f, 3.5f, 1.0f};
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  for (const auto& bad : {std::array<float, 3>{nan, 1, 1}, std::array<float, 3>{1, nan, nan},
                          std::array<float, 3>{inf, 1, 1}, std::array<float, 3>{1, 1, -inf}}) {
    std::vector<Neighbor> found;
    tree.search(finite, 4, found);  // the buffer holds a previous answer
    ASSERT_EQ(found.size(), 4u);
    tree.search(bad.data(), 4, found);
    EXPECT_TRUE(found.empty()) << "kept " << found.size() << " neighbours, first row " << found.front().id;
    std::vector<Neighbor> fresh;  // a never-used buffer: not row 0 of a zeroed one
    tree.search(bad.data(), 2, fresh);
    EXPECT_TRUE(fresh.empty());
  }
}

TEST(KnnRenderer, QueryWithoutNeighbourRendersNoCommand) {
  const TactileDataset d = countsDataset();
  const KnnRenderer renderer(d);
  const double good[4] = {1000, 1010, 990, 1000};
  ASSERT_TRUE(renderer.render(good, 4).found());
  for (const double bad : {kNaN, kInf, -kInf, 1e308, -1e300}) {
    for (size_t channel = 0; channel < 4; ++channel) {
      double s[4] = {1000, 1010, 990, 1000};
      s[channel] = bad;
      renderer.render(good, 4);  // the renderer's buffers hold a previous answer
      const RenderResult r = renderer.render(s, 4);
      EXPECT_FALSE(r.found()) << bad << " in channel " << channel;
      EXPECT_EQ(r.neighbors_used, 0);
      for (double m : r.command) EXPECT_TRUE(std::isnan(m)) << "a command " << m << " for " << bad;
    }
  }
}

TEST(SensedBounds, RefusesWrongLengthNonFiniteAndValuesFarOutsideTheDataset) {
  TactileDataset d;
  d.channels = 3;
  d.append({30, 30, 30}, {100.0, -2.0, 5.0});
  d.append({60, 60, 60}, {140.0, 2.0, 5.0});  // channel 3 never varies
  const SensedBounds b = SensedBounds::fromDataset(d);
  ASSERT_EQ(b.channels(), 3);
  // Span 40 -> [100 - 400, 140 + 400]; span 4 -> [-42, 42]; constant 5 -> 5 -+ 10 * max(1, 5).
  EXPECT_DOUBLE_EQ(b.low(0), -300.0);
  EXPECT_DOUBLE_EQ(b.high(0), 540.0);
  EXPECT_DOUBLE_EQ(b.low(1), -42.0);
  EXPECT_DOUBLE_EQ(b.high(1), 42.0);
  EXPECT_DOUBLE_EQ(b.low(2), -45.0);
  EXPECT_DOUBLE_EQ(b.high(2), 55.0);

  EXPECT_EQ(b.refusal(std::vector<double>{120.0, 0.0, 5.0}), "");
  EXPECT_EQ(b.refusal(std::vector<double>{540.0, -42.0, 55.0}), "");  // the bounds themselves pass
  EXPECT_EQ(b.refusal(std::vector<double>{120.0, 0.0}), "sensed vector of 2 channels, the dataset has 3");
  EXPECT_EQ(b.refusal(std::vector<double>{120.0, kNaN, 5.0}), "sensed channel s2 is not finite (nan)");
  EXPECT_EQ(b.refusal(std::vector<double>{120.0, 0.0, -kInf}), "sensed channel s3 is not finite (-inf)");
  EXPECT_EQ(b.refusal(std::vector<double>{1e308, 0.0, 5.0}),
            "sensed channel s1 = 1e+308 is outside [-300, 540] (the dataset's range widened by ten times its span)");
  EXPECT_NE(b.refusal(std::vector<double>{120.0, 42.5, 5.0}), "");
  EXPECT_NE(b.refusal(std::vector<double>{120.0, 0.0, -45.5}), "");
}

TEST(SensedBounds, TheRenderersBoundsPassEveryDatasetRow) {
  const TactileDataset d = countsDataset();
  const KnnRenderer renderer(d);
  for (size_t r = 0; r < d.size(); ++r) {
    const std::vector<double> s(d.sensedRow(r), d.sensedRow(r) + d.channels);
    ASSERT_EQ(renderer.bounds().refusal(s), "") << "row " << r;
  }
}

// Inside the bounds no standardised distance overflows, even for a dataset at
// the ends of float32 (bounds beyond what a float holds) or with one outlier
// among many rows (the smallest sigma for its span): every corner of the
// bounds renders to a row at a finite distance, inside the commands' range.
TEST(SensedBounds, EveryVectorInsideTheBoundsRendersAtAFiniteDistance) {
  TactileDataset d;
  d.channels = 3;
  for (int r = 0; r < 20000; ++r)
    d.append({30.0 + r % 100, 90.0, 150.0}, {r % 2 ? 3.0e38 : -3.0e38, r == 0 ? 1.0 : 0.0, 1000.0 + r % 7});
  const KnnRenderer renderer(d);
  const SensedBounds& b = renderer.bounds();
  ASSERT_GT(b.high(0), 3.4e39) << "ten spans beyond a float's range";
  for (int corner = 0; corner < 8; ++corner) {
    std::vector<double> s(3);
    for (int c = 0; c < 3; ++c) s[static_cast<size_t>(c)] = (corner >> c & 1) ? b.high(c) : b.low(c);
    ASSERT_EQ(b.refusal(s), "") << "corner " << corner;
    const RenderResult r = renderer.render(s.data(), 4);
    ASSERT_TRUE(r.found()) << "corner " << corner;
    EXPECT_TRUE(std::isfinite(r.nearest_distance)) << "corner " << corner;
    EXPECT_GE(r.command[0], 30.0);
    EXPECT_LE(r.command[0], 129.0);
  }
}
