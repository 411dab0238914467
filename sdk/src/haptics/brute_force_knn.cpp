#include "haptics/brute_force_knn.hpp"

#include <algorithm>

namespace onetip::haptics {

void bruteForceKnn(const float* points, size_t rows, int dims, const float* query, int k,
                   std::vector<Neighbor>& out) {
  const size_t want = std::min(static_cast<size_t>(std::max(k, 1)), rows);
  out.clear();
  out.reserve(want + 1);
  for (size_t r = 0; r < rows; ++r) {
    const Neighbor candidate{static_cast<std::uint32_t>(r),
                             squaredDistance(query, points + r * static_cast<size_t>(dims), dims)};
    if (out.size() == want && !closerThan(candidate, out.back())) continue;
    out.insert(std::upper_bound(out.begin(), out.end(), candidate, closerThan), candidate);
    if (out.size() > want) out.pop_back();
  }
}

}  // namespace onetip::haptics
