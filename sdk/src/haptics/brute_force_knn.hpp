// haptics/brute_force_knn.hpp — the reference k-nearest-neighbour search: a
// linear scan over every row with the SDK's distance and (distance, id)
// ordering (neighbor.hpp). Tests compare the k-d tree against it and the
// benchmark measures the tree's speed-up over it.
#pragma once

#include <cstddef>
#include <vector>

#include "haptics/neighbor.hpp"

namespace onetip::haptics {

// The min(k, rows) nearest of `rows` points (row-major, dims floats each) to
// `query`, closest first, written to `out`.
void bruteForceKnn(const float* points, size_t rows, int dims, const float* query, int k,
                   std::vector<Neighbor>& out);

}  // namespace onetip::haptics
