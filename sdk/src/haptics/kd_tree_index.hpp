// haptics/kd_tree_index.hpp — exact k-nearest-neighbour search in a k-d tree.
//
// Built on nanoflann (header-only, Debian libnanoflann-dev; kept in the .cpp)
// with the SDK's own metric and result set (neighbor.hpp): the squared
// Euclidean distance of float points (float lanes), and neighbours ordered by
// (distance, id). The result set reports a worst distance inflated by a
// relative 1e-5 (above the distance's float rounding) so that points at
// exactly the current k-th distance are still offered and ranked by id, and
// neither that rounding nor nanoflann's incremental bound (double) can prune a
// point the scan would keep: the ids returned are exactly those of a brute-force
// scan (brute_force_knn.hpp). Bit-identical rows (every no-contact row of a
// noise-free dataset) are stored once in the tree with their ids, so a query
// near them costs one distance instead of a scan of the ties. After the build
// the vectors are stored in the leaves' order (a leaf scan reads consecutive
// memory). Chosen over FLANN's KDTreeSingleIndex and the
// brute-force scan by tests/bench/haptics (see docs/haptics/README.md).
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "haptics/neighbor.hpp"

namespace onetip::haptics {

struct KdTreeOptions {
  int leaf_size = 24;   // points per leaf (nanoflann's leaf_max_size), 1..1024
  void validate() const;  // throws InputError naming the bad field
};

class KdTreeIndex {
 public:
  // points: rows x dims floats, row-major; the index keeps its own copy.
  KdTreeIndex(std::vector<float> points, int dims, const KdTreeOptions& options = {});
  ~KdTreeIndex();
  KdTreeIndex(const KdTreeIndex&) = delete;
  KdTreeIndex& operator=(const KdTreeIndex&) = delete;

  // The min(k, size()) nearest rows to `query` (dims floats), closest first.
  // `out` is resized; no allocation once it has held k neighbours. k >= 1.
  void search(const float* query, int k, std::vector<Neighbor>& out) const;

  size_t size() const noexcept;          // rows
  size_t distinctSize() const noexcept;  // distinct vectors in the tree
  int dims() const noexcept;
  const float* point(size_t row) const noexcept;
  // Bytes held: the points plus the tree (nodes and index permutation).
  size_t memoryBytes() const;

 private:
  struct Impl;
  static void storeInTreeOrder(Impl& impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace onetip::haptics
