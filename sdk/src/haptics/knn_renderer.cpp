#include "haptics/knn_renderer.hpp"

#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace onetip::haptics {

namespace {
const TactileDataset& checked(const TactileDataset& d) {
  if (d.size() == 0 || d.channels <= 0) throw InputError("tactile dataset is empty");
  if (d.sensed.size() != d.size() * static_cast<size_t>(d.channels))
    throw InputError("tactile dataset: sensed values do not fill " + std::to_string(d.size()) + " rows");
  return d;
}
}  // namespace

KnnRenderer::KnnRenderer(const TactileDataset& dataset, const KdTreeOptions& tree)
    : space_(SearchSpace::fromDataset(checked(dataset))),
      commands_(dataset.commands),
      index_(space_.map(dataset), dataset.channels, tree),
      bounds_(SensedBounds::fromDataset(dataset)),
      query_(static_cast<size_t>(dataset.channels)) {}

RenderResult KnnRenderer::render(const double* s, int n) const {
  if (n < 1) throw InputError("neighbors: must be at least 1");
  space_.apply(s, query_.data());
  index_.search(query_.data(), n, found_);
  return combine(found_);
}

RenderResult KnnRenderer::combine(const std::vector<Neighbor>& neighbors) const {
  RenderResult r;
  if (neighbors.empty()) {
    r.command.fill(std::numeric_limits<double>::quiet_NaN());
    r.nearest_distance = std::numeric_limits<double>::infinity();
    return r;
  }
  r.neighbors_used = static_cast<int>(neighbors.size());
  r.nearest_row = neighbors.front().id;
  r.nearest_distance = std::sqrt(neighbors.front().distance_sq);
  r.exact_match = neighbors.front().distance_sq <= kExactMatchDistanceSq;
  double total = 0.0;
  for (const Neighbor& q : neighbors) {
    if (r.exact_match && q.distance_sq > kExactMatchDistanceSq) break;  // sorted: the exact ones come first
    const double w = r.exact_match ? 1.0 : 1.0 / q.distance_sq;
    const float* m = commands_.data() + 3 * static_cast<size_t>(q.id);
    for (int i = 0; i < 3; ++i) r.command[static_cast<size_t>(i)] += w * m[i];
    total += w;
  }
  for (double& c : r.command) c /= total;
  return r;
}

}  // namespace onetip::haptics
