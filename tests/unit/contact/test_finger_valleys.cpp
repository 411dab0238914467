// splitAtValleys and labelFingerRegions on depth fields with a known answer:
// two dimples whose imprints join above the region cut are two regions, split
// at the valley; one dimple with ripples is one; the prominence rule at its
// threshold; each finger cut at its own peak.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "contact/finger_valleys.hpp"
#include "contact/grid_components.hpp"

using onetip::contact::labelFingerRegions;
using onetip::contact::labelGridComponents;
using onetip::contact::splitAtValleys;

namespace {

constexpr int kSide = 17;  // a 17 x 17 grid at 1.2 mm pitch, centred on the origin

double cellX(int id) { return (id % kSide - kSide / 2) * 1.2; }
double cellY(int id) { return (id / kSide - kSide / 2) * 1.2; }

double gaussian(double depth, double width, double x0, double y0, int id) {
  const double dx = cellX(id) - x0, dy = cellY(id) - y0;
  return depth * std::exp(-(dx * dx + dy * dy) / (width * width));
}

// Labels of the cells at or above `cut` (as the contact analyzer masks them), split at `fraction`.
std::vector<int> regions(const std::vector<double>& depth, double cut, double fraction, int* count) {
  std::vector<std::uint8_t> mask(depth.size());
  for (size_t i = 0; i < depth.size(); ++i) mask[i] = depth[i] >= cut;
  return splitAtValleys(kSide, kSide, mask, depth, fraction, count);
}

}  // namespace

TEST(FingerValleys, TwoDimplesJoinedAboveTheCutAreTwoRegionsSplitAtTheValley) {
  // Dimples 1.0 and 0.8 mm deep at x = -3 and +3 mm: between them the depth stays above the 0.4 mm cut,
  // so the mask is one connected area.
  std::vector<double> depth(kSide * kSide);
  for (int id = 0; id < kSide * kSide; ++id)
    depth[static_cast<size_t>(id)] = gaussian(1.0, 2.5, -3, 0, id) + gaussian(0.8, 2.5, 3, 0, id);
  std::vector<std::uint8_t> mask(depth.size());
  for (size_t i = 0; i < depth.size(); ++i) mask[i] = depth[i] >= 0.4;
  int components = 0;
  labelGridComponents(kSide, kSide, mask, &components);
  ASSERT_EQ(components, 1);
  int count = 0;
  const std::vector<int> label = regions(depth, 0.4, 0.3, &count);
  ASSERT_EQ(count, 2);
  // Independent answer: every masked cell away from the valley (|x| > one pitch) belongs to the dimple on
  // its side; the deeper dimple's region is the larger, numbered 0.
  for (int id = 0; id < kSide * kSide; ++id) {
    if (!mask[static_cast<size_t>(id)] || std::abs(cellX(id)) <= 1.2) continue;
    EXPECT_EQ(label[static_cast<size_t>(id)], cellX(id) < 0 ? 0 : 1) << "cell " << id;
  }
}

TEST(FingerValleys, OneDimpleWithRipplesIsOneRegion) {
  // Ripples of 3 % of the depth (far above a marker's noise against a 1 mm press) make local maxima
  // on the dimple's flank; none is prominent.
  std::vector<double> depth(kSide * kSide);
  for (int id = 0; id < kSide * kSide; ++id)
    depth[static_cast<size_t>(id)] =
        gaussian(1.0, 4.0, 0.3, -0.2, id) + 0.03 * std::sin(2.1 * cellX(id)) * std::cos(1.7 * cellY(id));
  int count = 0;
  const std::vector<int> label = regions(depth, 0.4, 0.3, &count);
  EXPECT_EQ(count, 1);
}

namespace {

// A 3 x 8 grid whose middle row holds `row` between two unmasked columns; the rows above and below are
// measured at zero depth, outside the mask. Returns the middle row's labels.
std::vector<int> splitRow(const std::vector<double>& row, double fraction, int* count) {
  const int cols = static_cast<int>(row.size()) + 2;
  std::vector<double> depth(static_cast<size_t>(3 * cols), 0.0);
  std::vector<std::uint8_t> mask(depth.size(), 0);
  for (size_t c = 0; c < row.size(); ++c) {
    depth[static_cast<size_t>(cols) + 1 + c] = row[c];
    mask[static_cast<size_t>(cols) + 1 + c] = std::isfinite(row[c]) ? 1 : 0;
  }
  const std::vector<int> label = splitAtValleys(3, cols, mask, depth, fraction, count);
  return {label.begin() + cols + 1, label.begin() + 2 * cols - 1};
}

}  // namespace

TEST(FingerValleys, APeakIsItsOwnRegionOnlyWhenItsValleyIsDeepEnough) {
  // Peaks 1.0 and 0.8, valley 0.5 between them; the lower peak's prominence is 0.3 / 0.8 = 0.375.
  const std::vector<double> row{0.6, 1.0, 0.7, 0.5, 0.8, 0.6};
  int count = 0;
  std::vector<int> label = splitRow(row, 0.35, &count);
  ASSERT_EQ(count, 2);
  EXPECT_EQ(label, (std::vector<int>{0, 0, 0, 1, 1, 1}));  // the valley cell joins its deepest neighbour's basin
  label = splitRow(row, 0.4, &count);
  EXPECT_EQ(count, 1);
  for (int l : label) EXPECT_EQ(l, 0);
}

TEST(FingerValleys, APeakOnlyThePatternShowsIsNotAFinger) {
  // The same row, but the lower peak's marker on the pattern's border (its imprint may rise beyond it)...
  const std::vector<double> depth{0.6, 1.0, 0.7, 0.5, 0.8};
  int count = 0;
  splitAtValleys(1, 5, std::vector<std::uint8_t>(depth.size(), 1), depth, 0.35, &count);
  EXPECT_EQ(count, 1);
  // ...or beside a marker that is not measured.
  const double lost = std::numeric_limits<double>::quiet_NaN();
  splitRow({0.6, 1.0, 0.7, 0.5, 0.8, lost}, 0.35, &count);
  EXPECT_EQ(count, 1);
}

TEST(FingerValleys, AFractionOfOneSplitsNothing) {
  int count = 0;
  const std::vector<int> label = splitRow({0.6, 1.0, 0.1, 0.01, 0.8, 0.6}, 1.0, &count);
  EXPECT_EQ(count, 1);
  for (int l : label) EXPECT_EQ(l, 0);
}

TEST(FingerValleys, EachFingerIsCutAtItsOwnPeak) {
  // Dimples 1.0 and 0.3 mm deep, 10 mm apart, both touches (beyond a 0.1 mm floor): the shallow one keeps the
  // cells at or above 40 % of its own peak, though all lie below 40 % of the deep one's.
  std::vector<double> depth(kSide * kSide);
  for (int id = 0; id < kSide * kSide; ++id)
    depth[static_cast<size_t>(id)] = gaussian(1.0, 1.8, -5, 0, id) + gaussian(0.3, 1.8, 5, 0, id);
  std::vector<double> cuts;
  int count = 0;
  const std::vector<int> label = labelFingerRegions(kSide, kSide, depth, depth, 0.1, 0.4, 0.3, cuts, &count);
  ASSERT_EQ(count, 2);
  double deep_peak = 0, shallow_peak = 0;
  for (int id = 0; id < kSide * kSide; ++id) {
    double& peak = cellX(id) < 0 ? deep_peak : shallow_peak;
    peak = std::max(peak, depth[static_cast<size_t>(id)]);
  }
  for (int id = 0; id < kSide * kSide; ++id) {
    const double peak = cellX(id) < 0 ? deep_peak : shallow_peak;
    const bool in = depth[static_cast<size_t>(id)] >= 0.4 * peak;
    EXPECT_EQ(label[static_cast<size_t>(id)] >= 0, in) << "cell " << id;
    if (in) {
      EXPECT_NEAR(cuts[static_cast<size_t>(label[static_cast<size_t>(id)])], 0.4 * peak, 1e-12) << "cell " << id;
    }
  }
  // One finger: the single cut at 40 % of its peak, the floor notwithstanding.
  for (int id = 0; id < kSide * kSide; ++id) depth[static_cast<size_t>(id)] = gaussian(0.2, 2.0, 0, 0, id);
  const std::vector<int> one = labelFingerRegions(kSide, kSide, depth, depth, 0.1, 0.4, 0.3, cuts, &count);
  ASSERT_EQ(count, 1);
  for (int id = 0; id < kSide * kSide; ++id)
    EXPECT_EQ(one[static_cast<size_t>(id)] >= 0, depth[static_cast<size_t>(id)] >= 0.4 * 0.2) << "cell " << id;
}
