#include "observable_truth.hpp"

#include <cmath>

#include "campaign_score.hpp"
#include "core/rotation.hpp"
#include "pose/adaptive_pose_options.hpp"
#include "pose/pose_uncertainty.hpp"

namespace onetip::poseval {

namespace {

// The truth's increment `truth` (S, mm) over an interval, less the turn that the markers sticking through it do
// not fix (see the header); the increment itself when they fix every direction.
Eigen::Isometry3d fixedPart(const Eigen::Isometry3d& truth, const ReplayFrame& before, const ReplayFrame& now,
                            double noise_mm) {
  std::vector<Eigen::Vector3d> points;
  for (size_t i = 0; i < now.gt_contact_markers.size() && i < before.gt_positions.size(); ++i)
    if (trulySticks(before, i) && trulySticks(now, i)) points.push_back(before.gt_positions[i]);
  if (points.empty()) return truth;
  Eigen::Vector3d m = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& q : points) m += q;
  m /= static_cast<double>(points.size());
  const double n = static_cast<double>(points.size());
  // stickInformation credits a set with one marker's information at its spread; these markers' noise is
  // independent, so the per-marker sigma is divided by sqrt(n) to give the set its n markers' information.
  const double sigma = std::sqrt(2.0) * noise_mm / std::sqrt(n);
  const pose::StickInformation info = pose::stickInformation(points, std::vector<double>(points.size(), 1.0), m,
                                                             sigma, pose::AdaptivePoseOptions{}.slip_sigmas * noise_mm);
  if (info.fixed_directions == 6) return truth;
  // About m the turn and the move decouple, so the unfixed turn is the projector's turn block applied to theta.
  const Eigen::AngleAxisd turn(truth.linear());
  const Eigen::Vector3d theta = turn.angle() * turn.axis();
  const Eigen::Vector3d seen = theta - info.unfixed_projector.topLeftCorner<3, 3>() * theta;
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  if (seen.norm() > 0) out.linear() = Eigen::AngleAxisd(seen.norm(), seen.normalized()).toRotationMatrix();
  out.translation() = truth * m - out.linear() * m;  // m goes where the truth takes it
  return out;
}

}  // namespace

bool noMarkerSticksThrough(const ReplayFrame& before, const ReplayFrame& now) {
  if (!before.gt_contact || !now.gt_contact) return false;
  for (size_t i = 0; i < now.gt_contact_markers.size(); ++i)
    if (trulySticks(before, i) && trulySticks(now, i)) return false;
  return true;
}

std::vector<Input6> observableTruth(const std::vector<ReplayFrame>& frames, const ObservableTruthOptions& options) {
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
      const Eigen::Isometry3d truth = motionFromInput6(f.gt, f.gt_c0) * motionFromInput6(prev.gt, f.gt_c0).inverse();
      reference = (options.unseen == UnseenMotion::unfixed_directions ? fixedPart(truth, prev, f, options.noise_mm)
                                                                      : truth) * reference;
    }
    out.push_back(input6FromMotion(reference, f.gt_c0));
  }
  return out;
}

}  // namespace onetip::poseval
