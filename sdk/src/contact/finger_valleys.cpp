#include "contact/finger_valleys.hpp"

#include <algorithm>
#include <cmath>

#include "contact/grid_components.hpp"

namespace onetip::contact {

namespace {

// Union-find over cells; a basin's root keeps its peak depth.
struct Basins {
  std::vector<int> parent;
  std::vector<double> peak;
  explicit Basins(size_t n) : parent(n, -1), peak(n, 0.0) {}
  int root(int i) {
    while (parent[static_cast<size_t>(i)] != i) {
      parent[static_cast<size_t>(i)] = parent[static_cast<size_t>(parent[static_cast<size_t>(i)])];
      i = parent[static_cast<size_t>(i)];
    }
    return i;
  }
};

// All eight neighbours of `id` are on the grid and measured: its depth is a
// maximum of the field, not only of what the pattern shows.
bool enclosed(int rows, int cols, int id, const std::vector<double>& depth) {
  const int r = id / cols, c = id % cols;
  if (r == 0 || c == 0 || r == rows - 1 || c == cols - 1) return false;
  for (int dr = -1; dr <= 1; ++dr)
    for (int dc = -1; dc <= 1; ++dc)
      if (!std::isfinite(depth[static_cast<size_t>((r + dr) * cols + c + dc)])) return false;
  return true;
}

}  // namespace

std::vector<int> splitAtValleys(int rows, int cols, const std::vector<int>& component, const std::vector<double>& depth,
                                double min_prominence_fraction, int* region_count) {
  const size_t n = component.size();
  std::vector<int> order;
  for (size_t i = 0; i < n; ++i)
    if (component[i] >= 0) order.push_back(static_cast<int>(i));
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return depth[static_cast<size_t>(a)] > depth[static_cast<size_t>(b)]; });
  Basins basins(n);
  std::vector<int> roots;
  for (int id : order) {
    const size_t i = static_cast<size_t>(id);
    const int r = id / cols, c = id % cols;
    int deepest = -1;  // the deepest taken neighbour
    roots.clear();
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc) {
        const int rr = r + dr, cc = c + dc;
        if ((dr == 0 && dc == 0) || rr < 0 || rr >= rows || cc < 0 || cc >= cols) continue;
        const int j = rr * cols + cc;
        if (basins.parent[static_cast<size_t>(j)] < 0) continue;  // not taken yet (or outside the mask)
        if (deepest < 0 || depth[static_cast<size_t>(j)] > depth[static_cast<size_t>(deepest)]) deepest = j;
        roots.push_back(basins.root(j));
      }
    if (deepest < 0) {  // a new peak
      basins.parent[i] = id;
      basins.peak[i] = depth[i];
      continue;
    }
    std::sort(roots.begin(), roots.end());
    roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
    const int top = *std::max_element(roots.begin(), roots.end(), [&](int a, int b) {
      return basins.peak[static_cast<size_t>(a)] < basins.peak[static_cast<size_t>(b)];
    });
    for (int other : roots) {
      const double peak = basins.peak[static_cast<size_t>(other)];
      const bool apart = enclosed(rows, cols, other, depth) && peak - depth[i] >= min_prominence_fraction * peak;
      if (other != top && !apart) basins.parent[static_cast<size_t>(other)] = top;
    }
    basins.parent[i] = basins.root(deepest);
  }
  std::vector<int> label(n, -1);
  for (int id : order) label[static_cast<size_t>(id)] = basins.root(id);
  const int count = rankLabelsBySize(label);
  if (region_count) *region_count = count;
  return label;
}

}  // namespace onetip::contact
