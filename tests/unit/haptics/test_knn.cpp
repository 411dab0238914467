// The k-d tree against the brute-force scan (ids and distances identical,
// ties by id), the renderer's Eq. 7 against an independent weighted mean,
// exact matches, constant channels, and the paper's reduced reachable spaces.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.hpp"
#include "haptics/brute_force_knn.hpp"
#include "haptics/display_grid.hpp"
#include "haptics/dof_reduction.hpp"
#include "haptics/kd_tree_index.hpp"
#include "haptics/knn_renderer.hpp"

using namespace onetip;
using namespace onetip::haptics;

namespace {

void expectSameAsBruteForce(const std::vector<float>& points, int dims, const std::vector<float>& queries, int k,
                            int leaf_size = 12) {
  const size_t rows = points.size() / static_cast<size_t>(dims);
  const KdTreeIndex tree(points, dims, KdTreeOptions{leaf_size});
  std::vector<Neighbor> a, b;
  for (size_t q = 0; q + static_cast<size_t>(dims) <= queries.size(); q += static_cast<size_t>(dims)) {
    tree.search(queries.data() + q, k, a);
    bruteForceKnn(points.data(), rows, dims, queries.data() + q, k, b);
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
      ASSERT_EQ(a[i].id, b[i].id) << "query " << q / dims << " rank " << i;
      ASSERT_EQ(a[i].distance_sq, b[i].distance_sq);
    }
  }
}

std::vector<float> uniform(size_t count, unsigned seed, float lo = -1.f, float hi = 1.f) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(lo, hi);
  std::vector<float> v(count);
  for (float& x : v) x = u(rng);
  return v;
}

}  // namespace

TEST(KdTree, MatchesBruteForceOnRandomData) {
  for (int dims : {2, 5, 20}) {
    const auto points = uniform(3000 * static_cast<size_t>(dims), 10 + static_cast<unsigned>(dims));
    const auto queries = uniform(200 * static_cast<size_t>(dims), 99, -1.5f, 1.5f);
    for (int k : {1, 4, 8, 33}) expectSameAsBruteForce(points, dims, queries, k);
  }
}

TEST(KdTree, MatchesBruteForceOnGridsWithTiesAndDuplicates) {
  // An integer 3-D grid, every point twice, embedded in 6-D: many exactly equal
  // distances, which both searches must break by row id.
  std::vector<float> points;
  for (int rep = 0; rep < 2; ++rep)
    for (int x = 0; x < 8; ++x)
      for (int y = 0; y < 8; ++y)
        for (int z = 0; z < 8; ++z) points.insert(points.end(), {float(x), float(y), float(z), float(x), 0.f, 1.f});
  std::vector<float> queries;
  for (int i = 0; i < 50; ++i) {  // on grid points, half-way between them, and outside
    const float a = float(i % 8), b = float((i * 3) % 8) + 0.5f * float(i % 2), c = float(i % 5) - 2.f;
    queries.insert(queries.end(), {a, b, c, a, 0.f, 1.f});
  }
  for (int k : {1, 2, 6, 8, 27}) {
    expectSameAsBruteForce(points, 6, queries, k, 1);
    expectSameAsBruteForce(points, 6, queries, k, 12);
  }
  // A tie at the k-th place resolves to the smaller id: the duplicate of a
  // query's exact grid point (id + 512) ranks right after the original.
  const KdTreeIndex tree(points, 6);
  std::vector<Neighbor> found;
  tree.search(points.data() + 6 * 100, 2, found);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].id, 100u);
  EXPECT_EQ(found[1].id, 612u);
}

TEST(KdTree, ReturnsAllPointsWhenKExceedsTheSize) {
  const auto points = uniform(5 * 3, 4);
  expectSameAsBruteForce(points, 3, uniform(30, 5), 9);
  const KdTreeIndex tree(points, 3);
  std::vector<Neighbor> found;
  tree.search(points.data(), 9, found);
  EXPECT_EQ(found.size(), 5u);
  EXPECT_THROW(KdTreeIndex({}, 3), InputError);
  EXPECT_THROW(KdTreeIndex(points, 3, KdTreeOptions{0}), InputError);
}

TEST(KnnRenderer, WeightedCommandMatchesEq7FromBruteForce) {
  std::mt19937 rng(7);
  std::normal_distribution<double> n01;
  TactileDataset d;
  d.channels = 6;
  const std::vector<double> channel_sd = {1.0, 10.0, 0.1, 500.0, 3.0, 2.0};
  for (int r = 0; r < 2000; ++r) {
    std::vector<double> s(6);
    for (size_t c = 0; c < 6; ++c) s[c] = 100.0 + channel_sd[c] * n01(rng);
    d.append({30.0 + r % 55 * 3.0, 30.0 + r / 55 % 55 * 3.0, 30.0 + r % 7 * 3.0}, s);
  }
  const KnnRenderer renderer(d);
  for (int q = 0; q < 100; ++q) {
    std::vector<double> s(6);
    for (size_t c = 0; c < 6; ++c) s[c] = 100.0 + channel_sd[c] * n01(rng);
    // Independent reference: standardise with a two-pass standard deviation,
    // scan every row, weight by 1 / d^2.
    std::vector<double> sd(6);
    for (size_t c = 0; c < 6; ++c) {
      double mean = 0, var = 0;
      for (size_t r = 0; r < d.size(); ++r) mean += d.sensedRow(r)[c] / double(d.size());
      for (size_t r = 0; r < d.size(); ++r) var += std::pow(d.sensedRow(r)[c] - mean, 2) / double(d.size());
      sd[c] = std::sqrt(var);
    }
    std::vector<std::pair<double, size_t>> dist;
    for (size_t r = 0; r < d.size(); ++r) {
      double d2 = 0;
      for (size_t c = 0; c < 6; ++c) d2 += std::pow((s[c] - d.sensedRow(r)[c]) / sd[c], 2);
      dist.push_back({d2, r});
    }
    std::sort(dist.begin(), dist.end());
    for (int n : {1, 4, 8}) {
      std::array<double, 3> expected{};
      double wsum = 0;
      for (int i = 0; i < n; ++i) {
        const double w = 1.0 / dist[static_cast<size_t>(i)].first;
        for (int j = 0; j < 3; ++j) expected[static_cast<size_t>(j)] += w * d.command(dist[static_cast<size_t>(i)].second)[j];
        wsum += w;
      }
      const RenderResult r = renderer.render(s.data(), n);
      EXPECT_EQ(r.neighbors_used, n);
      EXPECT_EQ(r.nearest_row, dist[0].second);
      // The renderer searches in float (standardised values to ~1e-7 relative):
      // weights agree to ~1e-5, commands to a few thousandths of a degree.
      for (size_t j = 0; j < 3; ++j) EXPECT_NEAR(r.command[j], expected[j] / wsum, 5e-3) << "n " << n;
      if (n == 1) {
        for (size_t j = 0; j < 3; ++j) EXPECT_DOUBLE_EQ(r.command[j], d.command(dist[0].second)[j]);
      }
    }
  }
}

TEST(KnnRenderer, ExactMatchesAndConstantChannels) {
  TactileDataset d;
  d.channels = 3;
  d.append({30, 30, 30}, {1.0, 5.0, 7.0});
  d.append({60, 90, 120}, {2.0, 5.0, 7.0});  // channel 2 and 3 never vary
  d.append({90, 90, 90}, {2.0, 5.0, 7.0});   // exact duplicate of row 1's vector
  d.append({195, 195, 195}, {4.0, 5.0, 7.0});
  const KnnRenderer renderer(d);
  EXPECT_EQ(renderer.scaling().constantChannels(), 2);
  // Eq. 9's summand counts only the informative channel: |1 - 3| / sigma_0,
  // sigma_0 = population sd of {1, 2, 2, 4} = sqrt(4.75 / 4).
  const double a[3] = {1.0, 5.0, 7.0}, b[3] = {3.0, 0.0, 0.0};
  EXPECT_NEAR(renderer.scaling().meanStandardizedError(a, b), 2.0 / std::sqrt(4.75 / 4.0), 1e-12);
  // Query equal to rows 1 and 2 in the only informative channel, far off in
  // the constant ones: an exact match, the mean of the two matching rows.
  const double s[3] = {2.0, 50.0, -7.0};
  const RenderResult r = renderer.render(s, 4);
  EXPECT_TRUE(r.exact_match);
  EXPECT_DOUBLE_EQ(r.command[0], 75.0);
  EXPECT_DOUBLE_EQ(r.command[1], 90.0);
  EXPECT_DOUBLE_EQ(r.command[2], 105.0);
  EXPECT_TRUE(std::isfinite(renderer.render(s, 1).command[0]));
  EXPECT_THROW(renderer.render(s, 0), InputError);
}

TEST(DofReduction, ReachableSpacesHaveThePapersSizesAndConstraints) {
  TactileDataset full;
  full.channels = 1;
  for (const auto& m : gridConfigurations(3.0)) full.append(m, {m[0] + 2 * m[1] + 3 * m[2]});
  EXPECT_EQ(full.size(), 166375u);
  struct Case {
    double step;
    DeviceDof dof;
    size_t rows;
  };
  for (const Case& c : {Case{3, DeviceDof::three, 166375}, Case{6, DeviceDof::two, 784}, Case{9, DeviceDof::one, 19},
                        Case{9, DeviceDof::three, 6859}, Case{6, DeviceDof::one, 28}, Case{3, DeviceDof::two, 3025}}) {
    const auto reduced = reduceDataset(full, GridSubset{c.step, c.dof, 30.0});
    EXPECT_EQ(reduced.size(), c.rows) << c.step << " deg " << int(c.dof) << "-DoF";
    for (size_t r = 0; r < reduced.size(); ++r) {
      const float* m = reduced.command(r);
      for (int i = 0; i < 3; ++i) EXPECT_EQ(std::fmod(m[i] - 30.0, c.step), 0.0);
      if (c.dof != DeviceDof::three) {
        EXPECT_EQ(m[1], m[2]);
      }
      if (c.dof == DeviceDof::one) {
        EXPECT_EQ(m[0], m[1]);
      }
      EXPECT_EQ(reduced.sensedRow(r)[0], m[0] + 2 * m[1] + 3 * m[2]);  // rows stay paired
    }
  }
  EXPECT_THROW(reduceDataset(full, GridSubset{4.0, DeviceDof::three, 31.5}), InputError);
  EXPECT_THROW(deviceDofFromInt(4), InputError);
}
