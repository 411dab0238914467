#include "observable_truth.hpp"

#include "campaign_score.hpp"
#include "core/rotation.hpp"

namespace onetip::poseval {

bool noMarkerSticksThrough(const ReplayFrame& before, const ReplayFrame& now) {
  if (!before.gt_contact || !now.gt_contact) return false;
  for (size_t i = 0; i < now.gt_contact_markers.size(); ++i)
    if (trulySticks(before, i) && trulySticks(now, i)) return false;
  return true;
}

std::vector<Input6> observableTruth(const std::vector<ReplayFrame>& frames) {
  std::vector<Input6> out;
  out.reserve(frames.size());
  Eigen::Isometry3d reference = Eigen::Isometry3d::Identity();  // the observable finger since onset (S, mm)
  for (size_t k = 0; k < frames.size(); ++k) {
    const ReplayFrame& f = frames[k];
    const bool continues = k > 0 && f.gt_contact && frames[k - 1].gt_contact && f.gt_c0 == frames[k - 1].gt_c0;
    if (!continues) {
      reference = motionFromInput6(f.gt, f.gt_c0);
      out.push_back(f.gt);
      continue;
    }
    const ReplayFrame& prev = frames[k - 1];
    if (noMarkerSticksThrough(prev, f)) {  // the turn held; the footprint's slide and the truth's depth
      Eigen::Vector3d move(0, 0, -(f.gt.dz - prev.gt.dz));
      if (f.gt_footprint_valid && prev.gt_footprint_valid) move.head<2>() = f.gt_footprint - prev.gt_footprint;
      reference.translation() += move;
    } else {  // the truth's own motion over the interval, so the offset is carried unchanged (on the right)
      reference = motionFromInput6(f.gt, f.gt_c0) * motionFromInput6(prev.gt, f.gt_c0).inverse() * reference;
    }
    out.push_back(input6FromMotion(reference, f.gt_c0));
  }
  return out;
}

}  // namespace onetip::poseval
