#include "contact/grid_components.hpp"

#include <algorithm>
#include <numeric>

namespace onetip::contact {

std::vector<int> labelGridComponents(int rows, int cols, const std::vector<std::uint8_t>& mask,
                                     int* component_count) {
  const int n = rows * cols;
  std::vector<int> label(static_cast<size_t>(n), -1);
  std::vector<int> sizes, first_ids, stack;
  for (int seed = 0; seed < n; ++seed) {
    if (!mask[static_cast<size_t>(seed)] || label[static_cast<size_t>(seed)] >= 0) continue;
    const int comp = static_cast<int>(sizes.size());
    sizes.push_back(0);
    first_ids.push_back(seed);
    stack.assign(1, seed);
    label[static_cast<size_t>(seed)] = comp;
    while (!stack.empty()) {
      const int id = stack.back();
      stack.pop_back();
      ++sizes.back();
      const int r = id / cols, c = id % cols;
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          const int rr = r + dr, cc = c + dc;
          if (rr < 0 || rr >= rows || cc < 0 || cc >= cols) continue;
          const int j = rr * cols + cc;
          if (!mask[static_cast<size_t>(j)] || label[static_cast<size_t>(j)] >= 0) continue;
          label[static_cast<size_t>(j)] = comp;
          stack.push_back(j);
        }
    }
  }
  std::vector<int> order(sizes.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return sizes[static_cast<size_t>(a)] != sizes[static_cast<size_t>(b)]
               ? sizes[static_cast<size_t>(a)] > sizes[static_cast<size_t>(b)]
               : first_ids[static_cast<size_t>(a)] < first_ids[static_cast<size_t>(b)];
  });
  std::vector<int> rank(sizes.size());
  for (size_t k = 0; k < order.size(); ++k) rank[static_cast<size_t>(order[k])] = static_cast<int>(k);
  for (int& l : label)
    if (l >= 0) l = rank[static_cast<size_t>(l)];
  if (component_count) *component_count = static_cast<int>(sizes.size());
  return label;
}

}  // namespace onetip::contact
