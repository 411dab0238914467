// tests/unit/pose/replay_metrics.hpp — accuracy figures of a replay against
// the simulator's ground truth (per-axis RMSE, stick/slip F1, region IoU,
// output steps beyond the true motion).
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "sim_replay.hpp"

namespace onetip::poseval {

using FramePredicate = std::function<bool(const ReplayFrame&)>;
using EstimateOf = std::function<Input6(const ReplayFrame&)>;

inline Input6 rawOf(const ReplayFrame& f) { return f.raw; }
inline Input6 composedOf(const ReplayFrame& f) { return f.composed; }
inline Input6 eulerSumOf(const ReplayFrame& f) { return f.euler_sum; }

struct AxisRmse {
  std::array<double, 6> rmse{};  // dx, dy, dz (mm), yaw, pitch, roll (deg)
  int frames = 0;
};
// Over frames where both the ground truth and the estimate are in contact and `keep` holds.
AxisRmse axisRmse(const std::vector<ReplayFrame>& frames, const EstimateOf& estimate, const FramePredicate& keep);

struct Classification {
  double precision = 0, recall = 0, f1 = 0;
  long true_positive = 0, false_positive = 0, false_negative = 0;
};
// Slip markers: estimate slip label vs the simulator's slip label, over frames both call contact.
Classification slipF1(const std::vector<ReplayFrame>& frames);
// Contact region vs the simulator's per-marker contact: pooled intersection over union.
double regionIoU(const std::vector<ReplayFrame>& frames);

// Largest amount by which |estimate_k - estimate_{k-1}| exceeds |gt_k - gt_{k-1}| per axis,
// over consecutive frames both in contact (both estimate and truth).
std::array<double, 6> worstExcessStep(const std::vector<ReplayFrame>& frames);

}  // namespace onetip::poseval
