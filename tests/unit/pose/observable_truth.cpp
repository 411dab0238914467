#include "observable_truth.hpp"

#include "campaign_score.hpp"

namespace onetip::poseval {

bool everyContactMarkerSlips(const ReplayFrame& f) { return f.gt_contact && countTrulySticking(f) == 0; }

std::vector<Input6> observableTruth(const std::vector<ReplayFrame>& frames) {
  std::vector<Input6> out;
  out.reserve(frames.size());
  for (size_t k = 0; k < frames.size(); ++k) {
    const ReplayFrame& f = frames[k];
    const bool continues = k > 0 && f.gt_contact && frames[k - 1].gt_contact;
    if (!continues || !everyContactMarkerSlips(f)) {
      Input6 o = f.gt;
      if (continues) {  // the offset left by earlier gross slip, carried
        const Input6& prev_gt = frames[k - 1].gt;
        const Input6& prev = out.back();
        o = Input6::fromArray({f.gt.dx + prev.dx - prev_gt.dx, f.gt.dy + prev.dy - prev_gt.dy,
                               f.gt.dz + prev.dz - prev_gt.dz, f.gt.yaw + prev.yaw - prev_gt.yaw,
                               f.gt.pitch + prev.pitch - prev_gt.pitch, f.gt.roll + prev.roll - prev_gt.roll});
      }
      out.push_back(o);
      continue;
    }
    Input6 o = out.back();  // the turn held
    if (f.gt_footprint_valid && frames[k - 1].gt_footprint_valid) {
      o.dx += f.gt_footprint.x() - frames[k - 1].gt_footprint.x();
      o.dy += f.gt_footprint.y() - frames[k - 1].gt_footprint.y();
    }
    o.dz += f.gt.dz - frames[k - 1].gt.dz;
    out.push_back(o);
  }
  return out;
}

}  // namespace onetip::poseval
