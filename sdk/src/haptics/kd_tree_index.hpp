// haptics/kd_tree_index.hpp — exact k-nearest-neighbour search in a k-d tree.
//
// The tree is built by nanoflann (header-only, Debian libnanoflann-dev; kept in
// the .cpp: sliding-midpoint splits on the dimension of largest spread). The
// search is the SDK's own: depth first, nearer child first, with the bounding
// box of every cell in all dimensions (nanoflann bounds a cell by its split
// planes only). On data near a low-dimensional manifold, such as a 3-DoF
// display's sensed vectors, a cell's vectors fill a small corner of the
// rectangle its splits define, so the full box prunes far more: median query
// 11.0 -> 8.6 us in tests/bench/haptics. Distances use the SDK's metric and
// result set (neighbor.hpp): the squared Euclidean distance of float points
// (float lanes), neighbours ordered by (distance, id). The result set reports a
// worst distance inflated by a relative 1e-5 (above the float rounding of both
// the point and the box distances) so that points at exactly the current k-th
// distance are still offered and ranked by id, and no rounding can prune a
// point the scan would keep: the ids returned are exactly those of a
// brute-force scan (brute_force_knn.hpp). Bit-identical rows (every no-contact
// row of a noise-free dataset) are stored once in the tree with their ids, so
// a query near them costs one distance instead of a scan of the ties. After
// the build the vectors are stored in the leaves' order (a leaf scan reads
// consecutive memory). Chosen over FLANN's KDTreeSingleIndex, nanoflann's own
// search and the brute-force scan by tests/bench/haptics (docs/haptics/README.md).
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
  // Only rows at a finite distance qualify: a query with a NaN or infinite
  // value has none, and `out` is then empty (never the previous call's rows).
  // `out` is resized; no allocation once it has held k neighbours. k >= 1.
  void search(const float* query, int k, std::vector<Neighbor>& out) const;

  size_t size() const noexcept;          // rows
  size_t distinctSize() const noexcept;  // distinct vectors in the tree
  int dims() const noexcept;
  const float* point(size_t row) const noexcept;
  // Bytes held: the points plus the tree (nodes, cell boxes and index permutation).
  size_t memoryBytes() const;

 private:
  struct Impl;
  static void storeInTreeOrder(Impl& impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace onetip::haptics
