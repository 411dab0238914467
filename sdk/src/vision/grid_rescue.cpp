#include "vision/grid_rescue.hpp"

#include <algorithm>
#include <cstdint>

#include "vision/grid_checks.hpp"

namespace onetip::vision {
namespace {

class Rescue {
 public:
  Rescue(const MarkerPattern& pattern, const ViewMarkers& m, const LatticeView& before, const std::vector<float>& spacing,
         const RescueLimits& limits, std::vector<int>& reject, std::vector<float>& confidence)
      : p_(pattern), m_(m), before_(before), spacing_(spacing), limits_(limits), reject_(reject), confidence_(confidence),
        passed_(m.valid), trusted_{m.rows, m.cols, &m.point, &passed_} {
    for (int id : reject) passed_[static_cast<size_t>(id)] = 0;
  }

  void run(std::vector<OffMotion> pending) {
    do {
      for (bool kept = true; kept && !pending.empty();) kept = singles(pending);
    } while (!pending.empty() && pair(pending));
  }

 private:
  bool linksPass(int id) const {
    const LinkCheck links = checkLinks(trusted_, before_, p_.rowOf(id), p_.colOf(id), limits_.max_link_stretch);
    return links.bad == 0 && links.crossed == 0;
  }

  // Distance in squares from the nearest of the three models' places (header).
  float residual(const OffMotion& off) const {
    const size_t i = static_cast<size_t>(off.id);
    float best = std::min(off.residual_squares, off.track_squares);
    if (const auto q = predictFromNeighbours(trusted_, p_.rowOf(off.id), p_.colOf(off.id)))
      best = std::min(best, static_cast<float>(cv::norm(m_.point[i] - *q)) / spacing_[i]);
    return best;
  }

  // Grade in 0..1 of a marker taken back alone, or below 0.
  float single(const OffMotion& off) const {
    const size_t i = static_cast<size_t>(off.id);
    const int row = p_.rowOf(off.id), col = p_.colOf(off.id);
    if (!linksPass(off.id)) return -1.0f;
    const auto margin = cellMargin(trusted_, row, col, m_.point[i]);
    if (margin && *margin > 0.0f && residual(off) <= limits_.near_swap_squares) return 1.0f;
    const float limit = limits_.rescue_fraction * spacing_[i];
    const auto worst = closeCompletion(trusted_, row, col, m_.point[i]);
    return worst && *worst <= limit ? 1.0f - *worst / limit : -1.0f;
  }

  void keep(int id, float grade) {
    confidence_[static_cast<size_t>(id)] = 0.5f * grade;
    passed_[static_cast<size_t>(id)] = 1;
    reject_.erase(std::find(reject_.begin(), reject_.end(), id));
  }

  // One round of single markers; whether any was taken back.
  bool singles(std::vector<OffMotion>& pending) {
    bool kept = false;
    std::vector<OffMotion> still;
    for (const OffMotion& off : pending) {
      const float grade = single(off);
      if (grade < 0.0f) {
        still.push_back(off);
        continue;
      }
      keep(off.id, grade);
      kept = true;
    }
    pending = std::move(still);
    return kept;
  }

  // The first pair of neighbouring pending markers inside their pair's cell;
  // whether one was taken back.
  bool pair(std::vector<OffMotion>& pending) {
    for (size_t x = 0; x < pending.size(); ++x) {
      for (size_t y = 0; y < pending.size(); ++y) {
        const int a = pending[x].id, b = pending[y].id;
        const int dr = p_.rowOf(b) - p_.rowOf(a), dc = p_.colOf(b) - p_.colOf(a);
        if (!((dr == 0 && dc == 1) || (dr == 1 && dc == 0))) continue;  // b after a along an axis
        if (residual(pending[x]) > limits_.near_swap_squares || residual(pending[y]) > limits_.near_swap_squares ||
            !linksPass(a) || !linksPass(b))
          continue;
        const auto margins = pairCellMargins(trusted_, p_.rowOf(a), p_.colOf(a), dr, dc, m_.point[static_cast<size_t>(a)],
                                             m_.point[static_cast<size_t>(b)]);
        if (!margins || margins->first <= 0.0f || margins->second <= 0.0f) continue;
        keep(a, 1.0f), keep(b, 1.0f);
        pending.erase(pending.begin() + static_cast<long>(std::max(x, y)));
        pending.erase(pending.begin() + static_cast<long>(std::min(x, y)));
        return true;
      }
    }
    return false;
  }

  const MarkerPattern& p_;
  const ViewMarkers& m_;
  const LatticeView& before_;
  const std::vector<float>& spacing_;
  const RescueLimits& limits_;
  std::vector<int>& reject_;
  std::vector<float>& confidence_;
  std::vector<std::uint8_t> passed_;
  LatticeView trusted_;
};

}  // namespace

void rescueOffMotion(const MarkerPattern& pattern, const ViewMarkers& m, const LatticeView& before,
                     const std::vector<float>& spacing, const std::vector<OffMotion>& off_motion,
                     const RescueLimits& limits, std::vector<int>& reject, std::vector<float>& confidence) {
  if (off_motion.empty() || limits.rescue_fraction <= 0.0f) return;
  Rescue(pattern, m, before, spacing, limits, reject, confidence).run(off_motion);
}

}  // namespace onetip::vision
