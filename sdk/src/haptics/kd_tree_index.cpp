#include "haptics/kd_tree_index.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <nanoflann.hpp>

#include "core/error.hpp"

namespace onetip::haptics {

namespace {

struct PointRows {
  std::vector<float> data;
  int dims = 0;
  size_t kdtree_get_point_count() const { return data.size() / static_cast<size_t>(dims); }
  float kdtree_get_pt(size_t row, size_t dim) const { return data[row * static_cast<size_t>(dims) + dim]; }
  const float* row(size_t r) const { return data.data() + r * static_cast<size_t>(dims); }
  template <class BBox>
  bool kdtree_get_bbox(BBox&) const {
    return false;
  }
};

// nanoflann's metric type: it fixes the element and distance types. nanoflann
// only builds the tree; KdTreeIndex::search walks BoxedNodes.
struct StandardisedL2 {
  using ElementType = float;
  using DistanceType = double;
  explicit StandardisedL2(const PointRows&) {}
};

// Keeps the k best rows by (distance, id) in a sorted array. The tree holds
// distinct vectors; each offers its rows (ascending ids) in turn.
class TieAwareResultSet {
 public:
  TieAwareResultSet(Neighbor* slots, size_t capacity, const std::vector<std::uint32_t>& group_start,
                    const std::vector<std::uint32_t>& group_rows)
      : slots_(slots), capacity_(capacity), group_start_(group_start), group_rows_(group_rows) {}
  size_t size() const { return count_; }
  bool full() const { return count_ == capacity_; }
  double worstDist() const {
    if (!full()) return std::numeric_limits<double>::infinity();
    const double w = slots_[capacity_ - 1].distance_sq;
    return w * (1.0 + 1e-5) + std::numeric_limits<double>::min();
  }
  void addPoint(double dist, std::uint32_t vector) {
    for (std::uint32_t g = group_start_[vector]; g < group_start_[vector + 1]; ++g)
      if (!addRow(dist, group_rows_[g])) break;
  }

 private:
  bool addRow(double dist, std::uint32_t id) {
    const Neighbor candidate{id, dist};
    if (full() && !closerThan(candidate, slots_[capacity_ - 1])) return false;
    size_t i = full() ? capacity_ - 1 : count_++;
    while (i > 0 && closerThan(candidate, slots_[i - 1])) {
      slots_[i] = slots_[i - 1];
      --i;
    }
    slots_[i] = candidate;
    return true;
  }

  Neighbor* slots_;
  size_t capacity_;
  const std::vector<std::uint32_t>& group_start_;
  const std::vector<std::uint32_t>& group_rows_;
  size_t count_ = 0;
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<StandardisedL2, PointRows, -1, std::uint32_t>;

// nanoflann's tree flattened into an array, each node with the bounding box of
// the vectors below it in every dimension (nanoflann keeps only the split
// dimension's bounds). On data near a low-dimensional manifold a cell's
// vectors fill a small part of the rectangle its splits define, so the full
// box gives a much tighter lower bound.
struct BoxedNodes {
  struct Node {
    std::int32_t child[2] = {-1, -1};  // -1: leaf
    std::uint32_t begin = 0, end = 0;  // vectors [begin, end) in leaf order
  };
  int dims = 0;
  std::vector<Node> nodes;
  std::vector<float> bounds;  // per node: low[dims] then high[dims]
  float* lowOf(std::int32_t id) { return bounds.data() + static_cast<size_t>(id) * 2 * static_cast<size_t>(dims); }
  float* highOf(std::int32_t id) { return lowOf(id) + dims; }
  const float* lowOf(std::int32_t id) const {
    return bounds.data() + static_cast<size_t>(id) * 2 * static_cast<size_t>(dims);
  }

  std::int32_t add(const Tree::Node* n, const PointRows& rows) {
    const auto id = static_cast<std::int32_t>(nodes.size());
    const auto d = static_cast<size_t>(dims);
    nodes.emplace_back();
    bounds.resize(bounds.size() + 2 * d);
    float* lo = lowOf(id);
    float* hi = highOf(id);
    if (n->child1 == nullptr && n->child2 == nullptr) {
      nodes[static_cast<size_t>(id)].begin = static_cast<std::uint32_t>(n->node_type.lr.left);
      nodes[static_cast<size_t>(id)].end = static_cast<std::uint32_t>(n->node_type.lr.right);
      std::fill(lo, lo + d, std::numeric_limits<float>::infinity());
      std::fill(hi, hi + d, -std::numeric_limits<float>::infinity());
      for (size_t v = n->node_type.lr.left; v < n->node_type.lr.right; ++v)
        for (size_t i = 0; i < d; ++i) {
          lo[i] = std::min(lo[i], rows.row(v)[i]);
          hi[i] = std::max(hi[i], rows.row(v)[i]);
        }
      return id;
    }
    const std::int32_t a = add(n->child1, rows), b = add(n->child2, rows);
    lo = lowOf(id);  // the array may have moved
    hi = highOf(id);
    for (size_t i = 0; i < d; ++i) {
      lo[i] = std::min(lowOf(a)[i], lowOf(b)[i]);
      hi[i] = std::max(highOf(a)[i], highOf(b)[i]);
    }
    auto& node = nodes[static_cast<size_t>(id)];
    node.child[0] = a;
    node.child[1] = b;
    return id;
  }

  // Squared distance from q to node's box (0 inside), in float: four lanes
  // at a time, then the remaining dimensions.
  double boxDistance(const float* q, std::int32_t node) const {
    using detail::Float4;
    using detail::load4;
    const float* lo = lowOf(node);
    const float* hi = lo + dims;
    const Float4 zero = {0, 0, 0, 0};
    Float4 acc = zero;
    int i = 0;
    for (; i + 4 <= dims; i += 4) {
      const Float4 x = load4(q + i), below = load4(lo + i) - x, above = x - load4(hi + i);
      const Float4 e = (below > zero ? below : zero) + (above > zero ? above : zero);
      acc += e * e;
    }
    float sum = (acc[0] + acc[1]) + (acc[2] + acc[3]);
    for (; i < dims; ++i) {
      const float e = std::max(lo[i] - q[i], 0.0f) + std::max(q[i] - hi[i], 0.0f);
      sum += e * e;
    }
    return sum;
  }
};

}  // namespace

void KdTreeOptions::validate() const {
  if (leaf_size < 1 || leaf_size > 1024) throw InputError("KdTreeOptions.leaf_size: must be in 1..1024");
}

struct KdTreeIndex::Impl {
  std::vector<float> points;               // every row, as given
  PointRows distinct;                      // the distinct vectors the tree holds
  std::vector<std::uint32_t> group_start;  // rows of distinct vector v:
  std::vector<std::uint32_t> group_rows;   //   group_rows[group_start[v] .. group_start[v+1])
  std::unique_ptr<Tree> tree;
  BoxedNodes boxes;
};

namespace {
// Groups bit-identical rows (ids ascending within a group, groups in order of
// their first row), so repeated vectors cost the search one distance.
void groupIdenticalRows(const std::vector<float>& points, int dims, std::vector<float>& distinct,
                        std::vector<std::uint32_t>& group_start, std::vector<std::uint32_t>& group_rows) {
  const auto d = static_cast<size_t>(dims);
  const size_t rows = points.size() / d;
  std::vector<std::uint32_t> order(rows);
  for (size_t i = 0; i < rows; ++i) order[i] = static_cast<std::uint32_t>(i);
  auto less = [&](std::uint32_t a, std::uint32_t b) {
    const int c = std::memcmp(points.data() + a * d, points.data() + b * d, d * sizeof(float));
    return c < 0 || (c == 0 && a < b);
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> groups;  // (first row, start in order)
  for (size_t i = 0; i < rows; ++i)
    if (i == 0 || std::memcmp(points.data() + order[i] * d, points.data() + order[i - 1] * d, d * sizeof(float)) != 0)
      groups.push_back({order[i], static_cast<std::uint32_t>(i)});
  std::sort(groups.begin(), groups.end());
  group_start.clear();
  group_rows.clear();
  distinct.clear();
  for (const auto& [first, start] : groups) {
    group_start.push_back(static_cast<std::uint32_t>(group_rows.size()));
    distinct.insert(distinct.end(), points.data() + first * d, points.data() + (first + 1) * d);
    for (size_t i = start; i < rows && std::memcmp(points.data() + order[i] * d, points.data() + first * d,
                                                   d * sizeof(float)) == 0;
         ++i)
      group_rows.push_back(order[i]);
  }
  group_start.push_back(static_cast<std::uint32_t>(group_rows.size()));
}
}  // namespace

KdTreeIndex::KdTreeIndex(std::vector<float> points, int dims, const KdTreeOptions& options)
    : impl_(std::make_unique<Impl>()) {
  options.validate();
  if (dims <= 0) throw InputError("KdTreeIndex: dims must be positive");
  if (points.empty() || points.size() % static_cast<size_t>(dims) != 0)
    throw InputError("KdTreeIndex: point buffer is empty or not a whole number of rows");
  if (points.size() / static_cast<size_t>(dims) > std::numeric_limits<std::uint32_t>::max())
    throw InputError("KdTreeIndex: more than 2^32 - 1 points");
  impl_->points = std::move(points);
  impl_->distinct.dims = dims;
  groupIdenticalRows(impl_->points, dims, impl_->distinct.data, impl_->group_start, impl_->group_rows);
  impl_->tree = std::make_unique<Tree>(dims, impl_->distinct,
                                       nanoflann::KDTreeSingleIndexAdaptorParams(static_cast<size_t>(options.leaf_size)));
  storeInTreeOrder(*impl_);
  impl_->boxes.dims = dims;
  impl_->boxes.add(impl_->tree->root_node, impl_->distinct);
  impl_->boxes.bounds.shrink_to_fit();
  impl_->boxes.nodes.shrink_to_fit();
}

// Rewrites the distinct vectors (and their row groups) in the order the tree's
// leaves visit them and makes the tree's index permutation the identity, so a
// leaf scan reads consecutive memory instead of rows scattered over the set.
void KdTreeIndex::storeInTreeOrder(Impl& impl) {
  auto& order = impl.tree->vAcc;
  const auto d = static_cast<size_t>(impl.distinct.dims);
  std::vector<float> data(impl.distinct.data.size());
  std::vector<std::uint32_t> start, rows;
  start.reserve(impl.group_start.size());
  rows.reserve(impl.group_rows.size());
  for (size_t i = 0; i < order.size(); ++i) {
    const std::uint32_t v = order[i];
    std::copy_n(impl.distinct.row(v), d, data.data() + i * d);
    start.push_back(static_cast<std::uint32_t>(rows.size()));
    rows.insert(rows.end(), impl.group_rows.begin() + impl.group_start[v],
                impl.group_rows.begin() + impl.group_start[v + 1]);
    order[i] = static_cast<std::uint32_t>(i);
  }
  start.push_back(static_cast<std::uint32_t>(rows.size()));
  impl.distinct.data = std::move(data);
  impl.group_start = std::move(start);
  impl.group_rows = std::move(rows);
}

KdTreeIndex::~KdTreeIndex() = default;

void KdTreeIndex::search(const float* query, int k, std::vector<Neighbor>& out) const {
  const size_t want = std::min(static_cast<size_t>(std::max(k, 1)), size());
  out.resize(want);
  TieAwareResultSet result(out.data(), want, impl_->group_start, impl_->group_rows);
  const BoxedNodes& boxes = impl_->boxes;
  const PointRows& rows = impl_->distinct;
  // Depth first, nearer child first; a child is entered only if its box is
  // within the current k-th distance (re-read after every accepted vector).
  auto visit = [&](auto&& self, std::int32_t id) -> void {
    const auto& node = boxes.nodes[static_cast<size_t>(id)];
    if (node.child[0] < 0) {
      for (std::uint32_t v = node.begin; v < node.end; ++v) {
        const double d = squaredDistance(query, rows.row(v), rows.dims);
        if (d < result.worstDist()) result.addPoint(d, v);
      }
      return;
    }
    const double d0 = boxes.boxDistance(query, node.child[0]), d1 = boxes.boxDistance(query, node.child[1]);
    const int near = d0 <= d1 ? 0 : 1;
    if (std::min(d0, d1) <= result.worstDist()) self(self, node.child[near]);
    if (std::max(d0, d1) <= result.worstDist()) self(self, node.child[1 - near]);
  };
  visit(visit, 0);
  out.resize(result.size());  // a query no row is a finite distance from (NaN, Inf) finds none
}

size_t KdTreeIndex::size() const noexcept { return impl_->points.size() / static_cast<size_t>(dims()); }
size_t KdTreeIndex::distinctSize() const noexcept { return impl_->distinct.kdtree_get_point_count(); }
int KdTreeIndex::dims() const noexcept { return impl_->distinct.dims; }
const float* KdTreeIndex::point(size_t row) const noexcept {
  return impl_->points.data() + row * static_cast<size_t>(dims());
}

size_t KdTreeIndex::memoryBytes() const {
  return (impl_->points.size() + impl_->distinct.data.size()) * sizeof(float) +
         (impl_->group_start.size() + impl_->group_rows.size()) * sizeof(std::uint32_t) +
         impl_->tree->usedMemory(*impl_->tree) + impl_->boxes.bounds.size() * sizeof(float) +
         impl_->boxes.nodes.size() * sizeof(BoxedNodes::Node);
}

}  // namespace onetip::haptics
