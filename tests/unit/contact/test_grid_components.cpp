#include <gtest/gtest.h>

#include "contact/grid_components.hpp"

using onetip::contact::labelGridComponents;

TEST(GridComponents, SeparatesBlobsAndSortsThemBySize) {
  // 5 x 6 grid: a 2x2 blob top-left, a 3-cell diagonal chain on the right.
  const int rows = 5, cols = 6;
  std::vector<std::uint8_t> mask(rows * cols, 0);
  auto set = [&](int r, int c) { mask[static_cast<size_t>(r * cols + c)] = 1; };
  set(0, 0);
  set(0, 1);
  set(1, 0);
  set(1, 1);
  set(2, 3);
  set(3, 4);
  set(4, 5);  // diagonal neighbours form one component
  int count = 0;
  const auto label = labelGridComponents(rows, cols, mask, &count);
  ASSERT_EQ(count, 2);
  EXPECT_EQ(label[0], 0);  // the 4-cell blob is the largest
  EXPECT_EQ(label[7], 0);
  EXPECT_EQ(label[2 * cols + 3], 1);
  EXPECT_EQ(label[4 * cols + 5], 1);
  EXPECT_EQ(label[2 * cols + 0], -1);
}

TEST(GridComponents, EmptyMaskHasNoComponent) {
  int count = -1;
  const auto label = labelGridComponents(3, 3, std::vector<std::uint8_t>(9, 0), &count);
  EXPECT_EQ(count, 0);
  for (int l : label) EXPECT_EQ(l, -1);
}

TEST(GridComponents, CellsOfDifferentGroupsNeverConnect) {
  // One row of five masked cells, the last two in another group: two components, the larger first.
  const std::vector<std::uint8_t> mask(5, 1);
  const std::vector<int> group{0, 0, 0, 1, 1};
  int count = 0;
  const auto label = labelGridComponents(1, 5, mask, group, &count);
  ASSERT_EQ(count, 2);
  EXPECT_EQ(label, (std::vector<int>{0, 0, 0, 1, 1}));
}
