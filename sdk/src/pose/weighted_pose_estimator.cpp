#include "pose/weighted_pose_estimator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contact/stick_probability.hpp"
#include "core/rotation.hpp"
#include "pose/onset_reference.hpp"
#include "pose/step_limit.hpp"

namespace onetip::pose {

using contact::MarkerLabel;

WeightedPoseEstimator::WeightedPoseEstimator(const AdaptivePoseOptions& options)
    : options_(options), uncertainty_(options.uncertainty) {}

void WeightedPoseEstimator::reset() {
  active_ = false;
  pose_ = last_increment_ = Eigen::Isometry3d::Identity();
  history_.clear();
  std::fill(anchored_.begin(), anchored_.end(), 0);
}

void WeightedPoseEstimator::anchor(int id, const Eigen::Vector3d& p) {
  const size_t i = static_cast<size_t>(id);
  anchor_[i] = pose_.inverse() * p;
  anchored_at_[i] = p;
  anchored_[i] = 1;
}

int WeightedPoseEstimator::trackedRegion(const contact::ContactField& field) const {
  int best = -1, best_count = 0;
  for (size_t r = 0; r < field.regions.size(); ++r) {
    int count = 0;
    for (int id : field.regions[r].markers) count += anchored_[static_cast<size_t>(id)];
    if (count > best_count) {
      best = static_cast<int>(r);
      best_count = count;
    }
  }
  return best;
}

PoseStep WeightedPoseEstimator::start(const contact::ContactField& field, const MarkerField& now) {
  reset();
  const size_t n = now.position.size();
  anchor_.assign(n, Eigen::Vector3d::Zero());
  anchored_at_.assign(n, Eigen::Vector3d::Zero());
  anchored_.assign(n, 0);
  weight_.assign(n, 1.0);
  drift_mm_.assign(n, 0.0);
  drift_sd_.assign(n, 1.0);
  active_ = true;
  const contact::ContactRegion& region = field.regions.front();
  c0_ = onsetReferencePoint(field, now, region.markers, region.rest_centroid);
  for (int id : region.markers)
    if (now.valid[static_cast<size_t>(id)]) anchor(id, now.position[static_cast<size_t>(id)]);
  remember(field, now, region);
  uncertainty_.reset(c0_);
  PoseStep step;
  step.active = step.onset = true;
  step.region = 0;
  step.state = ContactState::stick;
  step.onset_centroid = c0_;
  step.thresholds = t_;
  step.labels.assign(n, MarkerLabel::outside);
  step.stick_probability.assign(n, 0.0);
  for (int id : region.markers)
    if (anchored_[static_cast<size_t>(id)]) {
      step.labels[static_cast<size_t>(id)] = MarkerLabel::stick;
      step.stick_probability[static_cast<size_t>(id)] = 1.0;
      ++step.n_stick;
    }
  return step;
}

void WeightedPoseEstimator::remember(const contact::ContactField& field, const MarkerField& now,
                                     const contact::ContactRegion& region) {
  history_.push_back({now, field.displacement, region.cut_mm, region.markers, region.footprint_centre, pose_,
                      static_cast<double>(region.markers.size())});
  while (static_cast<int>(history_.size()) > t_.window_frames) history_.pop_front();
}

std::optional<FootprintEvidence> WeightedPoseEstimator::footprint(const contact::ContactField& field,
                                                                  const std::vector<int>& members,
                                                                  const MarkerField& now) const {
  if (static_cast<int>(history_.size()) < t_.window_frames) return std::nullopt;
  const ContactSnapshot& old = history_[history_.size() - static_cast<size_t>(t_.window_frames)];
  const CommonFootprints common = commonFootprints(old, field, members, now);
  FootprintEvidence f;
  f.carried = pose_ * old.pose.inverse() * common.before;
  f.seen = common.after;
  Eigen::Vector3d travel = common.after - common.before;
  travel.z() = 0;
  // A region that grows or a press that deepens moves the footprint centre over the finger: its model
  // error grows without bound as either change approaches macro_size_change of the whole.
  const double size = static_cast<double>(members.size());
  const double change =
      std::max(std::abs(size - old.region_size) / old.region_size,
               std::abs(common.depth_after - common.depth_before) / std::max(common.depth_before, 1e-9));
  const double trust = 1.0 - change / options_.macro_size_change;
  if (trust <= 0) return std::nullopt;
  f.sd_mm = 0.5 * std::max(t_.macro_drift_mm, options_.macro_drift_ratio * travel.norm()) / trust;
  return f;
}

Eigen::Isometry3d WeightedPoseEstimator::solve(WeightedIncrementProblem& problem) const {
  // The objective is not convex: its minimum is sought from three starts and the cheapest kept. Last
  // frame's weights (the markers that stuck go on sticking); none sticking (the footprint and the
  // surface carry the finger: a stick set that stays put while the footprint moves on is left behind);
  // and graduated non-convexity from every marker sticking (nothing assumed).
  WeightedIncrementProblem from_none = problem, from_all = problem;
  for (WeightedMarker& m : from_none.markers) m.weight = 0;
  const Eigen::Isometry3d warm = solveByReweighting(problem, last_increment_);
  const Eigen::Isometry3d slid = solveByReweighting(from_none, last_increment_);
  const Eigen::Isometry3d graduated = solveByGraduatedNonConvexity(from_all, last_increment_);
  const double cost_warm = truncatedCost(problem, warm), cost_slid = truncatedCost(from_none, slid),
               cost_graduated = truncatedCost(from_all, graduated);
  if (cost_slid < cost_warm && cost_slid <= cost_graduated) {
    problem = from_none;
    return slid;
  }
  if (cost_graduated < cost_warm) {
    problem = from_all;
    return graduated;
  }
  return warm;
}

PoseStep WeightedPoseEstimator::update(const contact::ContactField& field, const MarkerField& now,
                                       const EstimatorThresholds& thresholds) {
  t_ = thresholds;
  if (!active_ || anchored_.size() != now.position.size()) return start(field, now);
  const int tracked = trackedRegion(field);
  if (tracked < 0) return start(field, now);
  const contact::ContactRegion& region = field.regions[static_cast<size_t>(tracked)];
  const MarkerField& before = history_.back().markers;

  // Anchored markers that left the region are forgotten; those merely not measured keep their anchor.
  std::vector<std::uint8_t> member(now.position.size(), 0);
  for (int id : region.markers) member[static_cast<size_t>(id)] = 1;
  for (size_t i = 0; i < anchored_.size(); ++i)
    if (anchored_[i] && !member[i] && now.valid[i]) anchored_[i] = 0;

  WeightedIncrementProblem problem;
  problem.centre = pose_ * c0_;
  problem.prior_turn_sd_rad = options_.uncertainty.unseen_turn_deg_per_sqrt_s * kRadPerDeg * std::sqrt(t_.frame_s);
  problem.prior_slide_sd_mm = options_.uncertainty.unseen_slide_mm_per_sqrt_s * std::sqrt(t_.frame_s);
  std::vector<int> ids;
  for (int id : region.markers) {
    const size_t i = static_cast<size_t>(id);
    if (!anchored_[i] || !now.valid[i] || !before.valid[i]) continue;
    const Eigen::Vector3d normal = field.normal_valid[i] ? field.normal[i] : Eigen::Vector3d::Zero().eval();
    // A sticking marker's residual: two measurements' noise, and the marker layer's departure from the
    // finger's rigid motion, a share f of its travel since it was anchored.
    const double travel = options_.uncertainty.relative_increment_error * (now.position[i] - anchored_at_[i]).norm();
    const double sd = std::sqrt(2.0 * t_.noise_mm * t_.noise_mm + travel * travel / 3.0);
    const Eigen::Vector3d& u = field.displacement[i];
    const Eigen::Vector3d from_rest = u.norm() > 3 * t_.noise_mm ? u.normalized() : Eigen::Vector3d::Zero().eval();
    problem.markers.push_back(
        {pose_ * anchor_[i], before.position[i], now.position[i], normal, weight_[i], sd, 1.0, from_rest});
    ids.push_back(id);
  }
  problem.footprint = footprint(field, region.markers, now);

  PoseStep step;
  step.active = true;
  step.thresholds = t_;
  step.onset_centroid = c0_;
  step.region = tracked;
  Eigen::Isometry3d increment = solve(problem);
  increment = limitIncrement(increment, pose_ * c0_, t_.max_step_mm, t_.max_step_rad, step.step_limited);
  pose_ = increment * pose_;
  last_increment_ = increment;

  for (size_t k = 0; k < ids.size(); ++k) {
    const size_t i = static_cast<size_t>(ids[k]);
    weight_[i] = problem.markers[k].weight;
    drift_mm_[i] = (pose_ * anchor_[i] - now.position[i]).norm();
    drift_sd_[i] = problem.markers[k].sd_mm;
  }
  report(now, ids, increment, step);
  // Slipping markers stick again (below); new members are anchored.
  for (int id : region.markers) {
    const size_t i = static_cast<size_t>(id);
    if (!now.valid[i]) continue;
    if (!anchored_[i]) {
      anchor(id, now.position[i]);
      weight_[i] = 1;
    } else if (weight_[i] < 0.5) {
      // It sticks again where it was a window ago: only a marker that has stuck for a whole window
      // carries the finger again (one dragged along for a frame looks rigid too).
      const ContactSnapshot& old = history_.front();
      const bool seen = old.markers.valid[i];
      anchor_[i] = (seen ? old.pose : pose_).inverse() * (seen ? old.markers.position[i] : now.position[i]);
      anchored_at_[i] = seen ? old.markers.position[i] : now.position[i];
    }
  }
  remember(field, now, region);
  step.increment = increment;
  step.pose = pose_;
  return step;
}

void WeightedPoseEstimator::report(const MarkerField& now, const std::vector<int>& ids,
                                   const Eigen::Isometry3d& increment, PoseStep& step) {
  step.labels.assign(now.position.size(), MarkerLabel::outside);
  step.stick_probability.assign(now.position.size(), 0.0);
  std::vector<Eigen::Vector3d> points;
  std::vector<double> weights;
  double weighted_square = 0, total = 0;
  const double bound = std::sqrt(kStickChi2);
  for (int id : ids) {
    const size_t i = static_cast<size_t>(id);
    const bool sticks = weight_[i] >= 0.5;
    step.labels[i] = sticks ? MarkerLabel::stick : MarkerLabel::slip;
    // In units of the marker's own sd s_i: the stick component is then a unit Gaussian (bound sqrt(chi2_3)),
    // the slip component uniform within a frame's largest step.
    step.stick_probability[i] =
        contact::stickProbability(drift_mm_[i] / drift_sd_[i], bound, t_.max_step_mm / drift_sd_[i]);
    (sticks ? step.n_stick : step.n_slip)++;
    if (!sticks) continue;
    points.push_back(now.position[i]);
    weights.push_back(step.stick_probability[i]);
    weighted_square += step.stick_probability[i] * drift_mm_[i] * drift_mm_[i];
    total += step.stick_probability[i];
  }
  step.state = step.n_slip == 0    ? ContactState::stick
               : step.n_stick == 0 ? ContactState::slip
                                   : ContactState::partial_slip;
  step.model = step.n_slip == 0 ? PoseModel::kabsch : step.n_stick == 0 ? PoseModel::centroid : PoseModel::stick_slip;
  const double sigma = std::max(t_.noise_mm, total > 0 ? std::sqrt(weighted_square / (3 * total)) : 0.0);
  uncertainty_.add(stickInformation(points, weights, pose_ * c0_, sigma, t_.slip_mm), increment, t_.frame_s);
  step.sd = uncertainty_.sd();
}

}  // namespace onetip::pose
