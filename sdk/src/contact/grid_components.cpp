#include "contact/grid_components.hpp"

#include <algorithm>

namespace onetip::contact {

std::vector<int> labelGridComponents(int rows, int cols, const std::vector<std::uint8_t>& mask, int* component_count) {
  return labelGridComponents(rows, cols, mask, std::vector<int>(mask.size(), 0), component_count);
}

std::vector<int> labelGridComponents(int rows, int cols, const std::vector<std::uint8_t>& mask,
                                     const std::vector<int>& group, int* component_count) {
  const int n = rows * cols;
  std::vector<int> label(static_cast<size_t>(n), -1);
  std::vector<int> stack;
  int components = 0;
  for (int seed = 0; seed < n; ++seed) {
    if (!mask[static_cast<size_t>(seed)] || label[static_cast<size_t>(seed)] >= 0) continue;
    const int comp = components++;
    stack.assign(1, seed);
    label[static_cast<size_t>(seed)] = comp;
    while (!stack.empty()) {
      const int id = stack.back();
      stack.pop_back();
      const int r = id / cols, c = id % cols;
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          const int rr = r + dr, cc = c + dc;
          if (rr < 0 || rr >= rows || cc < 0 || cc >= cols) continue;
          const int j = rr * cols + cc;
          if (!mask[static_cast<size_t>(j)] || label[static_cast<size_t>(j)] >= 0 ||
              group[static_cast<size_t>(j)] != group[static_cast<size_t>(id)])
            continue;
          label[static_cast<size_t>(j)] = comp;
          stack.push_back(j);
        }
    }
  }
  const int count = rankLabelsBySize(label);
  if (component_count) *component_count = count;
  return label;
}

int rankLabelsBySize(std::vector<int>& label) {
  const size_t n = label.size();
  std::vector<int> sizes(n, 0), first_id(n, -1), used;
  for (size_t i = 0; i < n; ++i) {
    const int l = label[i];
    if (l < 0) continue;
    if (sizes[static_cast<size_t>(l)]++ == 0) {
      first_id[static_cast<size_t>(l)] = static_cast<int>(i);
      used.push_back(l);
    }
  }
  std::stable_sort(used.begin(), used.end(), [&](int a, int b) {
    const size_t ua = static_cast<size_t>(a), ub = static_cast<size_t>(b);
    return sizes[ua] != sizes[ub] ? sizes[ua] > sizes[ub] : first_id[ua] < first_id[ub];
  });
  std::vector<int> rank(n, -1);
  for (size_t k = 0; k < used.size(); ++k) rank[static_cast<size_t>(used[k])] = static_cast<int>(k);
  for (int& l : label)
    if (l >= 0) l = rank[static_cast<size_t>(l)];
  return static_cast<int>(used.size());
}

}  // namespace onetip::contact
