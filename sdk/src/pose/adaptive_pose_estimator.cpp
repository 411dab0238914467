#include "pose/adaptive_pose_estimator.hpp"

#include <algorithm>
#include <cmath>

#include "contact/footprint_centre.hpp"
#include "core/error.hpp"
#include "core/rotation.hpp"
#include "pose/centroid_motion.hpp"
#include "pose/rigid_fit.hpp"

namespace onetip::pose {

using contact::MarkerLabel;

std::string_view toString(PoseModel m) noexcept {
  switch (m) {
    case PoseModel::kabsch: return "kabsch";
    case PoseModel::stick_slip: return "stick_slip";
    case PoseModel::centroid: return "centroid";
    case PoseModel::none: break;
  }
  return "none";
}

void AdaptivePoseOptions::validate() const {
  stick_slip.validate();
  solver.validate();
  auto positive = [](double v, const char* name) {
    if (!(v > 0) || !std::isfinite(v)) throw InputError(std::string("pose options: ") + name + " must be a positive number");
  };
  positive(macro_drift_mm, "macro_drift_mm");
  positive(macro_tilt_gate_deg, "macro_tilt_gate_deg");
  positive(macro_size_change, "macro_size_change");
  positive(macro_drift_ratio, "macro_drift_ratio");
  positive(macro_exit_lag_mm, "macro_exit_lag_mm");
  positive(robust_scale_mm, "robust_scale_mm");
  positive(position_noise_mm, "position_noise_mm");
  if (!(rotation_significance >= 0)) throw InputError("pose options: rotation_significance must not be negative");
  positive(min_rotation_spread_mm, "min_rotation_spread_mm");
  if (macro_confirm_frames < 1) throw InputError("pose options: macro_confirm_frames must be at least 1");
  if (min_macro_markers < 1) throw InputError("pose options: min_macro_markers must be at least 1");
  positive(max_step_mm, "max_step_mm");
  positive(max_step_deg, "max_step_deg");
  if (macro_exit_window < 2) throw InputError("pose options: macro_exit_window must be at least 2");
}

AdaptivePoseEstimator::AdaptivePoseEstimator(AdaptivePoseOptions options)
    : options_(options), classifier_(options.stick_slip) {
  options_.validate();
}

void AdaptivePoseEstimator::reset() {
  active_ = false;
  macro_slip_ = false;
  macro_frames_ = 0;
  macro_suspect_frames_ = 0;
  pose_ = Eigen::Isometry3d::Identity();
  history_.clear();
}

int AdaptivePoseEstimator::trackedRegion(const contact::ContactField& field) const {
  int best = 0, best_count = -1;
  for (size_t r = 0; r < field.regions.size(); ++r) {
    int count = 0;
    for (int id : field.regions[r].markers) count += classifier_.label(id) != MarkerLabel::outside ? 1 : 0;
    if (count > best_count) {
      best = static_cast<int>(r);
      best_count = count;
    }
  }
  return best;
}

PoseStep AdaptivePoseEstimator::start(const contact::ContactField& field, const MarkerField& now) {
  PoseStep step;
  active_ = true;
  macro_slip_ = false;
  macro_frames_ = 0;
  macro_suspect_frames_ = 0;
  pose_ = Eigen::Isometry3d::Identity();
  const contact::ContactRegion& region = field.regions.front();
  c0_ = region.rest_centroid;
  classifier_.reset(now.size());
  classifier_.anchorNew(region.markers, now, pose_);
  history_.clear();
  remember(field, now, region);
  step.active = step.onset = true;
  step.region = 0;
  step.model = PoseModel::none;
  step.state = ContactState::stick;
  step.n_stick = static_cast<int>(classifier_.withLabel(MarkerLabel::stick).size());
  step.onset_centroid = c0_;
  step.labels = classifier_.labels();
  return step;
}

namespace {

// Fit of the anchored markers `ids` (references T a_i) to their positions now,
// trimmed of markers that drift from their anchors by more than the slip
// threshold, lagging ones first (rigid_fit.hpp; a marker relaxes along minus
// its tangential displacement u_t): robust Kabsch when the kept markers spread
// enough to fix a rotation, else translation only. `ids` becomes the kept set.
RigidFit fitAnchored(const contact::StickSlipClassifier& classifier, const contact::ContactField& field,
                     std::vector<int>& ids, const MarkerField& now, const Eigen::Isometry3d& pose,
                     const AdaptivePoseOptions& o, bool& rotation_supported) {
  std::vector<Eigen::Vector3d> from, to, relax;
  for (int id : ids) {
    const size_t i = static_cast<size_t>(id);
    from.push_back(pose * classifier.anchor(id));
    to.push_back(now.position[i]);
    const Eigen::Vector3d& u = field.displacement[i];
    const Eigen::Vector3d& n = field.normal[i];
    const Eigen::Vector3d tangential = u - u.dot(n) * n;
    const double size = tangential.norm();
    relax.push_back(size > 1e-9 ? Eigen::Vector3d(-tangential / size) : Eigen::Vector3d::Zero());
  }
  const TrimmedFit trimmed =
      fitRigidMotionTrimmed(from, to, relax, o.robust_scale_mm, o.stick_slip.slip_threshold_mm);
  if (trimmed.fit.ok) {
    size_t kept = 0;
    for (size_t i = 0; i < from.size(); ++i)
      if (trimmed.inlier[i]) {
        from[kept] = from[i];
        to[kept] = to[i];
        ids[kept++] = ids[i];
      }
    from.resize(kept);
    to.resize(kept);
    ids.resize(kept);
  }
  // Rotation noise of a fit over n points of RMS extent e: sigma_d / (e sqrt(n)),
  // sigma_d the noise of a marker's drift (two positions); smaller rotations
  // are not applied (a real one keeps growing against the anchors).
  const Eigen::Vector2d spread = planarSpread(from);
  const auto significant = [&](const RigidFit& fit, double extent) {
    const double sigma = std::sqrt(2.0) * o.position_noise_mm / (extent * std::sqrt(static_cast<double>(from.size())));
    return fit.ok && Eigen::AngleAxisd(fit.motion.linear()).angle() >= o.rotation_significance * sigma;
  };
  rotation_supported = trimmed.fit.ok && spread.x() >= o.min_rotation_spread_mm;
  if (rotation_supported && significant(trimmed.fit, spread.x())) return trimmed.fit;
  rotation_supported = false;
  if (spread.x() < o.min_rotation_spread_mm && spread.y() >= o.min_rotation_spread_mm) {
    // A stick set along a line (a small contact twisting about its centre).
    const RigidFit yaw = fitRotationAboutZ(from, to);
    if (significant(yaw, spread.y())) return yaw;
  }
  return fitTranslation(from, to);
}

RigidFit fitConsecutive(const std::vector<int>& members, const MarkerField& before, const MarkerField& now,
                        bool translation_only = false) {
  std::vector<Eigen::Vector3d> from, to;
  for (int id : members) {
    const size_t i = static_cast<size_t>(id);
    if (!before.valid[i] || !now.valid[i]) continue;
    from.push_back(before.position[i]);
    to.push_back(now.position[i]);
  }
  return translation_only ? fitTranslation(from, to) : fitRigidMotion(from, to);
}

double tiltBetween(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  const Eigen::Vector3d za = a.linear().col(2), zb = b.linear().col(2);
  return std::atan2(za.cross(zb).norm(), za.dot(zb));
}

}  // namespace

Eigen::Isometry3d AdaptivePoseEstimator::solveIncrement(const contact::ContactField& field, const MarkerField& now,
                                                        PoseStep& step) {
  const MarkerField& before = history_.back().markers;
  const std::vector<int>& members = field.regions[static_cast<size_t>(step.region)].markers;
  const Eigen::Isometry3d centroid_step = centroidStep(field, members, now);
  const ModelPolicy policy = options_.policy;

  if (policy == ModelPolicy::centroid_only || (policy == ModelPolicy::adaptive && macro_slip_)) {
    step.model = PoseModel::centroid;
    if (macro_slip_) classifier_.markAllSlipping(now, centroid_step * pose_);
    return centroid_step;
  }
  if (policy == ModelPolicy::kabsch_only) {
    const RigidFit fit = fitConsecutive(members, before, now);
    step.model = fit.ok ? PoseModel::kabsch : PoseModel::centroid;
    step.solver_failed = !fit.ok;
    if (fit.ok) classifier_.classify(now, field.normal, fit.motion * pose_);
    return fit.ok ? fit.motion : centroid_step;
  }

  bool rotation_supported = false;
  std::vector<int> stick_ids = classifier_.withLabel(MarkerLabel::stick);
  RigidFit fit = fitAnchored(classifier_, field, stick_ids, now, pose_, options_, rotation_supported);
  if (fit.ok && classifier_.classify(now, field.normal, fit.motion * pose_) > 0) {
    stick_ids = classifier_.withLabel(MarkerLabel::stick);
    fit = fitAnchored(classifier_, field, stick_ids, now, pose_, options_, rotation_supported);
  }
  std::vector<StickCorrespondence> stick;
  for (int id : stick_ids)
    stick.push_back({pose_ * classifier_.anchor(id), now.position[static_cast<size_t>(id)]});
  std::vector<SlipCorrespondence> slip;
  for (int id : classifier_.withLabel(MarkerLabel::slip)) {
    const size_t i = static_cast<size_t>(id);
    if (before.valid[i] && field.normal_valid[i]) slip.push_back({before.position[i], now.position[i], field.normal[i]});
  }
  const int ns = static_cast<int>(stick.size()), nl = static_cast<int>(slip.size());
  if (!stickSlipSolvable(ns, nl) || !fit.ok) {
    // Eq. 16 fails: macroscopic slip when the contact is developed enough to tell.
    step.model = PoseModel::centroid;
    if (policy == ModelPolicy::adaptive && ns + nl >= options_.min_macro_markers) enterMacroSlip(now, centroid_step);
    return centroid_step;
  }
  if ((nl == 0 && policy == ModelPolicy::adaptive) || !rotation_supported) {
    step.model = PoseModel::kabsch;
    return fit.motion;
  }
  const StickSlipSolution sol = solveStickSlipMotion(stick, slip, fit.motion, options_.solver);
  step.model = sol.ok ? PoseModel::stick_slip : PoseModel::centroid;
  step.solver_failed = !sol.ok;
  return sol.ok ? sol.motion : centroid_step;
}

void AdaptivePoseEstimator::enterMacroSlip(const MarkerField& now, const Eigen::Isometry3d& increment) {
  macro_slip_ = true;
  macro_suspect_frames_ = 0;
  macro_frames_ = 0;
  classifier_.markAllSlipping(now, increment * pose_);
}

void AdaptivePoseEstimator::checkMacroSlip(const contact::ContactField& field, const MarkerField& now,
                                           const contact::ContactRegion& region, Eigen::Isometry3d& increment) {
  const int window = options_.macro_exit_window;
  if (static_cast<int>(history_.size()) < window) return;
  const Frame& old = history_[history_.size() - static_cast<size_t>(window)];
  const Eigen::Isometry3d next = increment * pose_;
  const double size = static_cast<double>(region.markers.size());
  if (tiltBetween(next, old.pose) > options_.macro_tilt_gate_deg * kRadPerDeg ||
      std::abs(size - old.region_size) > options_.macro_size_change * old.region_size)
    return;
  // Where the footprint would be had it stayed fixed on the finger, and where it is.
  const auto [before, after] = commonFootprints(old, field, region.markers, now);
  Eigen::Vector3d drift = after - next * old.pose.inverse() * before;
  Eigen::Vector3d travel = after - before;
  drift.z() = 0;
  travel.z() = 0;
  if (drift.norm() <= std::max(options_.macro_drift_mm, options_.macro_drift_ratio * travel.norm())) {
    macro_suspect_frames_ = 0;
    return;
  }
  // A drift seen in consecutive frames: a footprint jittering because markers
  // come and go is not mistaken for the finger sliding away.
  if (++macro_suspect_frames_ < options_.macro_confirm_frames) return;
  // The finger slides while the markers stay behind: catch up once, then follow the footprint.
  Eigen::Isometry3d catch_up = Eigen::Isometry3d::Identity();
  catch_up.translation() = drift;
  increment = catch_up * increment;
  enterMacroSlip(now, increment);
}

bool AdaptivePoseEstimator::macroSlipEnded(const contact::ContactField& field, const std::vector<int>& members,
                                           const MarkerField& now) const {
  const int window = options_.macro_exit_window;
  if (macro_frames_ < window || static_cast<int>(history_.size()) < window) return false;
  const Frame& old = history_[history_.size() - static_cast<size_t>(window)];
  const RigidFit fit = fitConsecutive(members, old.markers, now);
  if (!fit.ok) return false;
  const auto [before, after] = commonFootprints(old, field, members, now);
  Eigen::Vector3d lag = after - fit.motion * before;
  lag.z() = 0;
  return lag.norm() < options_.macro_exit_lag_mm;
}

void AdaptivePoseEstimator::remember(const contact::ContactField& field, const MarkerField& now,
                                     const contact::ContactRegion& region) {
  history_.push_back({now, field.displacement, field.region_cut_mm, region.markers, region.footprint_centre, pose_,
                      static_cast<double>(region.markers.size())});
  while (static_cast<int>(history_.size()) > options_.macro_exit_window) history_.pop_front();
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> AdaptivePoseEstimator::commonFootprints(
    const Frame& before, const contact::ContactField& field, const std::vector<int>& members,
    const MarkerField& now) const {
  // Both footprint centres over the markers of either frame's region seen in
  // both frames, so a marker lost or found does not move the centre.
  std::vector<std::uint8_t> used(static_cast<size_t>(now.size()), 0);
  for (int id : members) used[static_cast<size_t>(id)] = 1;
  for (int id : before.members) used[static_cast<size_t>(id)] = 1;
  std::vector<Eigen::Vector3d> p0, p1;
  std::vector<double> n0, n1;
  for (size_t i = 0; i < used.size(); ++i) {
    if (!used[i] || !before.markers.valid[i] || !now.valid[i] || !field.valid[i]) continue;
    p0.push_back(before.markers.position[i]);
    n0.push_back(-before.displacement[i].z());
    p1.push_back(now.position[i]);
    n1.push_back(-field.displacement[i].z());
  }
  if (p0.empty()) return {before.footprint, before.footprint};
  return {contact::footprintCentre(p0, n0, before.cut_mm), contact::footprintCentre(p1, n1, field.region_cut_mm)};
}

Eigen::Isometry3d AdaptivePoseEstimator::centroidStep(const contact::ContactField& field, const std::vector<int>& members,
                                                      const MarkerField& now) const {
  if (!macro_slip_ && static_cast<int>(members.size()) < options_.min_macro_markers) {
    // A small contact's footprint is too coarse: its markers' mean motion.
    const RigidFit fit = fitConsecutive(members, history_.back().markers, now, true);
    if (fit.ok) return fit.motion;
  }
  const auto [before, after] = commonFootprints(history_.back(), field, members, now);
  return centroidMotion(before, after);
}

Eigen::Isometry3d AdaptivePoseEstimator::limitStep(const Eigen::Isometry3d& increment, bool& limited) const {
  const Eigen::Vector3d c = pose_ * c0_;
  const Eigen::Vector3d d = increment * c - c;
  const Eigen::AngleAxisd aa(increment.linear());
  double s = 1;
  if (d.norm() > options_.max_step_mm) s = std::min(s, options_.max_step_mm / d.norm());
  if (aa.angle() > options_.max_step_deg * kRadPerDeg) s = std::min(s, options_.max_step_deg * kRadPerDeg / aa.angle());
  limited = s < 1;
  if (!limited) return increment;
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = Eigen::AngleAxisd(s * aa.angle(), aa.axis()).toRotationMatrix();
  out.translation() = c + s * d - out.linear() * c;
  return out;
}

PoseStep AdaptivePoseEstimator::update(const contact::ContactField& field, const MarkerField& now) {
  if (!field.in_contact || field.status != contact::ContactFieldStatus::ok) {
    reset();
    return {};
  }
  if (!active_) return start(field, now);

  PoseStep step;
  step.active = true;
  step.onset_centroid = c0_;
  step.region = trackedRegion(field);
  const contact::ContactRegion& region = field.regions[static_cast<size_t>(step.region)];
  classifier_.retain(region.markers, now);

  Eigen::Isometry3d increment = solveIncrement(field, now, step);
  if (options_.policy == ModelPolicy::adaptive && !macro_slip_ &&
      static_cast<int>(region.markers.size()) >= options_.min_macro_markers)
    checkMacroSlip(field, now, region, increment);
  increment = limitStep(increment, step.step_limited);
  pose_ = increment * pose_;

  if (macro_slip_) {
    ++macro_frames_;
    if (macroSlipEnded(field, region.markers, now)) {
      macro_slip_ = false;
      classifier_.markAllSticking(now, pose_);
    }
  }
  classifier_.anchorNew(region.markers, now, pose_);

  remember(field, now, region);

  step.n_stick = static_cast<int>(classifier_.withLabel(MarkerLabel::stick).size());
  step.n_slip = static_cast<int>(classifier_.withLabel(MarkerLabel::slip).size());
  if (macro_slip_ || (step.n_stick == 0 && step.n_slip > 0)) step.state = ContactState::slip;
  else step.state = step.n_slip > 0 ? ContactState::partial_slip : ContactState::stick;
  step.increment = increment;
  step.pose = pose_;
  step.labels = classifier_.labels();
  return step;
}

}  // namespace onetip::pose
