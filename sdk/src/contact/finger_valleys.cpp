#include "contact/finger_valleys.hpp"

#include <algorithm>
#include <cmath>
#include <span>

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

std::vector<int> splitAtValleys(int rows, int cols, const std::vector<std::uint8_t>& mask,
                                const std::vector<double>& depth, double min_prominence_fraction, int* region_count) {
  const size_t n = mask.size();
  std::vector<int> order;
  for (size_t i = 0; i < n; ++i)
    if (mask[i]) order.push_back(static_cast<int>(i));
  std::sort(order.begin(), order.end(), [&](int a, int b) {  // deepest first; ties: the first cell first
    const double da = depth[static_cast<size_t>(a)], db = depth[static_cast<size_t>(b)];
    return da != db ? da > db : a < b;
  });
  Basins basins(n);
  for (int id : order) {
    const size_t i = static_cast<size_t>(id);
    const int r = id / cols, c = id % cols;
    int deepest = -1;            // the deepest taken neighbour
    int roots[8], distinct = 0;  // the basins of the taken neighbours
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc) {
        const int rr = r + dr, cc = c + dc;
        if ((dr == 0 && dc == 0) || rr < 0 || rr >= rows || cc < 0 || cc >= cols) continue;
        const int j = rr * cols + cc;
        if (basins.parent[static_cast<size_t>(j)] < 0) continue;  // not taken yet (or outside the mask)
        if (deepest < 0 || depth[static_cast<size_t>(j)] > depth[static_cast<size_t>(deepest)]) deepest = j;
        const int root = basins.root(j);
        if (std::find(roots, roots + distinct, root) == roots + distinct) roots[distinct++] = root;
      }
    if (deepest < 0) {  // a new peak
      basins.parent[i] = id;
      basins.peak[i] = depth[i];
      continue;
    }
    const int top = *std::max_element(roots, roots + distinct, [&](int a, int b) {
      return basins.peak[static_cast<size_t>(a)] < basins.peak[static_cast<size_t>(b)];
    });
    for (const int other : std::span<const int>(roots, static_cast<size_t>(distinct))) {
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

std::vector<int> labelFingerRegions(int rows, int cols, const std::vector<double>& depth,
                                    const std::vector<double>& normal, double floor, double region_fraction,
                                    double min_prominence_fraction, std::vector<double>& cuts, int* region_count) {
  const size_t n = depth.size();
  double deepest = 0;
  for (size_t i = 0; i < n; ++i)
    if (std::isfinite(depth[i])) deepest = std::max(deepest, normal[i]);
  const double seen = std::min(floor, region_fraction * deepest);
  std::vector<std::uint8_t> mask(n, 0);
  for (size_t i = 0; i < n; ++i) mask[i] = std::isfinite(depth[i]) && depth[i] >= seen;
  int fingers = 0;
  const std::vector<int> finger = splitAtValleys(rows, cols, mask, depth, min_prominence_fraction, &fingers);
  std::vector<double> peak(static_cast<size_t>(fingers), 0.0);
  for (size_t i = 0; i < n; ++i)
    if (finger[i] >= 0)
      peak[static_cast<size_t>(finger[i])] = std::max(peak[static_cast<size_t>(finger[i])], normal[i]);
  // Each finger's pieces above its own cut (cells of different fingers never connect).
  for (size_t i = 0; i < n; ++i)
    mask[i] = finger[i] >= 0 && depth[i] >= region_fraction * peak[static_cast<size_t>(finger[i])];
  int count = 0;
  const std::vector<int> label = labelGridComponents(rows, cols, mask, finger, &count);
  cuts.assign(static_cast<size_t>(count), 0.0);
  for (size_t i = 0; i < n; ++i)
    if (label[i] >= 0) cuts[static_cast<size_t>(label[i])] = region_fraction * peak[static_cast<size_t>(finger[i])];
  if (region_count) *region_count = count;
  return label;
}

}  // namespace onetip::contact
