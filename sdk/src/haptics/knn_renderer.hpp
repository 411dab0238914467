// haptics/knn_renderer.hpp — the data-driven tactile renderer f_n (journal
// paper, Eq. 2-8): sensed vector s -> motor command m-bar.
//
//   x      = standardise(s)                  x_i = s_i / sigma_i (channel_scaling.hpp),
//                                            on principal axes (search_space.hpp: a
//                                            rotation, so distances are unchanged)
//   nu_n   = the n nearest dataset rows to x (exact, k-d tree; ties by row id)
//   m-bar  = sum_q w_q m_q / sum_q w_q,  w_q = 1 / |x - x_q|^2        (Eq. 7)
// When the nearest row matches exactly (|x - x_q|^2 <= 1e-20, far below float
// resolution, where w would overflow) the weights are infinite; m-bar is then
// the plain mean of the commands of the rows at that distance. n = 1 is the plain nearest neighbour (Eq. 3). Commands are in
// degrees; the result stays inside the convex hull of the dataset commands.
// A query no row is a finite distance from (a NaN or infinite value, or one
// so large it overflows the float search space) has no neighbour: the result
// has neighbors_used 0 and a NaN command, which every device driver refuses
// (it retracts), so no stale or default command can stand in for it.
//
// render() reuses internal buffers, so one renderer must not be used from two
// threads at once (build one per thread; building is cheap next to loading).
#pragma once

#include <array>
#include <vector>

#include "haptics/kd_tree_index.hpp"
#include "haptics/search_space.hpp"
#include "haptics/sensed_bounds.hpp"
#include "haptics/tactile_dataset.hpp"

namespace onetip::haptics {

constexpr double kExactMatchDistanceSq = 1e-20;

struct RenderResult {
  std::array<double, 3> command{};  // m-bar, degrees (NaN when nothing was found)
  int neighbors_used = 0;           // min(n, dataset rows); 0: no row qualified
  bool found() const noexcept { return neighbors_used > 0; }
  bool exact_match = false;         // the nearest row is at distance ~0
  double nearest_distance = 0.0;    // standardised distance to the nearest row
  std::uint32_t nearest_row = 0;
};

class KnnRenderer {
 public:
  explicit KnnRenderer(const TactileDataset& dataset, const KdTreeOptions& tree = {});

  // s: channels() values in sensor units; n >= 1 neighbours.
  RenderResult render(const double* s, int n) const;
  // Eq. 7 over given neighbours (closest first) of this renderer's dataset.
  RenderResult combine(const std::vector<Neighbor>& neighbors) const;

  int channels() const noexcept { return space_.dims(); }
  size_t size() const noexcept { return index_.size(); }
  const ChannelScaling& scaling() const noexcept { return space_.scaling(); }
  const SearchSpace& space() const noexcept { return space_; }
  const KdTreeIndex& index() const noexcept { return index_; }
  // The sensed vectors this dataset can answer (sensed_bounds.hpp).
  const SensedBounds& bounds() const noexcept { return bounds_; }
  const std::vector<float>& commands() const noexcept { return commands_; }

 private:
  SearchSpace space_;
  std::vector<float> commands_;
  KdTreeIndex index_;
  SensedBounds bounds_;
  mutable std::vector<float> query_;
  mutable std::vector<Neighbor> found_;
};

}  // namespace onetip::haptics
