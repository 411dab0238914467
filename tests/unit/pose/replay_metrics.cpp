#include "replay_metrics.hpp"

#include <algorithm>
#include <cmath>

namespace onetip::poseval {

AxisRmse axisRmse(const std::vector<ReplayFrame>& frames, const EstimateOf& estimate, const FramePredicate& keep) {
  AxisRmse out;
  std::array<double, 6> sq{};
  for (const auto& f : frames) {
    if (!f.gt_contact || !f.contact || !keep(f)) continue;
    const auto e = estimate(f).asArray(), g = f.gt.asArray();
    for (size_t k = 0; k < 6; ++k) sq[k] += (e[k] - g[k]) * (e[k] - g[k]);
    ++out.frames;
  }
  for (size_t k = 0; k < 6; ++k) out.rmse[k] = out.frames ? std::sqrt(sq[k] / out.frames) : 0.0;
  return out;
}

Classification slipF1(const std::vector<ReplayFrame>& frames) {
  Classification c;
  for (const auto& f : frames) {
    if (!f.gt_contact || !f.contact) continue;
    for (size_t i = 0; i < f.slip.size(); ++i) {
      const bool truth = f.gt_slip[i] != 0, said = f.slip[i] != 0;
      c.true_positive += truth && said;
      c.false_positive += !truth && said;
      c.false_negative += truth && !said;
    }
  }
  const double tp = static_cast<double>(c.true_positive);
  c.precision = tp + c.false_positive > 0 ? tp / (tp + c.false_positive) : 1.0;
  c.recall = tp + c.false_negative > 0 ? tp / (tp + c.false_negative) : 1.0;
  c.f1 = c.precision + c.recall > 0 ? 2 * c.precision * c.recall / (c.precision + c.recall) : 0.0;
  return c;
}

double regionIoU(const std::vector<ReplayFrame>& frames) {
  long inter = 0, uni = 0;
  for (const auto& f : frames) {
    if (!f.gt_contact || !f.contact) continue;
    for (size_t i = 0; i < f.region.size(); ++i) {
      const bool a = f.region[i] != 0, b = f.gt_contact_markers[i] != 0;
      inter += a && b;
      uni += a || b;
    }
  }
  return uni > 0 ? static_cast<double>(inter) / static_cast<double>(uni) : 1.0;
}

std::array<double, 6> worstExcessStep(const std::vector<ReplayFrame>& frames) {
  std::array<double, 6> worst{};
  for (size_t k = 1; k < frames.size(); ++k) {
    const auto& a = frames[k - 1];
    const auto& b = frames[k];
    if (!a.contact || !b.contact || !a.gt_contact || !b.gt_contact) continue;
    const auto ea = a.raw.asArray(), eb = b.raw.asArray(), ga = a.gt.asArray(), gb = b.gt.asArray();
    for (size_t i = 0; i < 6; ++i)
      worst[i] = std::max(worst[i], std::abs(eb[i] - ea[i]) - std::abs(gb[i] - ga[i]));
  }
  return worst;
}

}  // namespace onetip::poseval
