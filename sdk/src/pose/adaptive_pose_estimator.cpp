#include "pose/adaptive_pose_estimator.hpp"

#include <algorithm>
#include <cmath>

#include "contact/contact_analyzer.hpp"
#include "contact/stick_probability.hpp"
#include "core/rotation.hpp"
#include "pose/anchored_fit.hpp"
#include "pose/centroid_motion.hpp"
#include "pose/contact_cap.hpp"
#include "pose/onset_reference.hpp"
#include "pose/step_limit.hpp"
#include "pose/stick_set_creep.hpp"
#include "pose/touching_markers.hpp"

namespace onetip::pose {

using contact::MarkerLabel;

AdaptivePoseEstimator::AdaptivePoseEstimator(AdaptivePoseOptions options)
    : options_(options), weighted_(options), uncertainty_(options.uncertainty) {
  options_.validate();
  t_ = deriveThresholds(options_, SensorSelf{});
}

void AdaptivePoseEstimator::reset() {
  weighted_.reset();
  active_ = false;
  macro_slip_ = false;
  macro_frames_ = 0;
  macro_suspect_frames_ = 0;
  pose_ = Eigen::Isometry3d::Identity();
  history_.clear();
}

int AdaptivePoseEstimator::trackedRegion(const contact::ContactField& field) const {
  int best = -1, best_count = 0;
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
  c0_ = onsetReferencePoint(field, now, region.markers, region.rest_centroid);
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
  uncertainty_.reset(c0_);
  reportUncertainty(now, Eigen::Isometry3d::Identity(), step);
  return step;
}

namespace {

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

  if (macro_slip_ && ++macro_frames_ >= t_.window_frames) {
    if (const std::optional<Eigen::Isometry3d> back = restick(field, members, now)) {
      macro_slip_ = false;
      step.model = PoseModel::kabsch;
      step.stuck_again = true;
      return *back;
    }
  }
  if (policy == ModelPolicy::centroid_only || (policy == ModelPolicy::adaptive && macro_slip_)) {
    step.model = PoseModel::centroid;
    if (macro_slip_) classifier_.markAllSlipping(now, centroid_step * pose_);
    return centroid_step;
  }
  if (policy == ModelPolicy::kabsch_only) {
    const RigidFit fit = fitConsecutive(members, before, now, 0);
    step.model = fit.ok ? PoseModel::kabsch : PoseModel::centroid;
    step.solver_failed = !fit.ok;
    if (fit.ok) classifier_.classify(now, field.normal, fit.motion * pose_);
    return fit.ok ? fit.motion : centroid_step;
  }

  // The stick fits take the labelled markers the finger can be touching
  // (touching_markers.hpp) on a developed contact, when enough are left: on a
  // smaller one every marker is at the edge. Touching markers detached while
  // none of them sticks stick again first (detachedUnderTheFinger). The cap's
  // concave core narrows the stick set to the markers that stick last; only
  // while the stick test sees them creep before the footprint test's floor
  // (slip threshold below the drift floor): noisier, a creeping core would
  // hide a slide from both.
  const bool region_developed = static_cast<int>(members.size()) >= options_.min_macro_markers;
  const double core_spread = t_.slip_mm < t_.macro_drift_mm ? options_.min_rotation_spread_pitches : 0.0;
  const std::vector<std::uint8_t> touching =
      region_developed ? touchingMarkers(field, members, now.rows, now.cols, t_.noise_mm, core_spread)
                       : std::vector<std::uint8_t>{};
  const auto stickSet = [&]() {
    std::vector<int> ids = classifier_.withLabel(MarkerLabel::stick), touched;
    if (!region_developed) return ids;
    for (int id : ids)
      if (touching[static_cast<size_t>(id)]) touched.push_back(id);
    return static_cast<int>(touched.size()) >= options_.min_thin_stick_markers ? touched : ids;
  };
  if (region_developed)  // anchored where they were a frame ago: the fit keeps this frame's motion
    classifier_.reattach(detachedUnderTheFinger(members, touching, classifier_.labels(), before, now,
                                                options_.min_thin_stick_markers),
                         before, pose_);
  // A smaller contact's fit is carried by its cap when the trim would drop most of it (fitAnchoredOnTheCap).
  const std::vector<std::uint8_t> cap = region_developed
                                            ? std::vector<std::uint8_t>{}
                                            : capMarkers(field, members, now.rows, now.cols, t_.noise_mm);
  std::vector<int> stick_ids = stickSet();
  const RotationTests rotation_tests{options_.rotation_significance, options_.thin_turn_significance,
                                     options_.thin_rigidity_sigmas};
  AnchoredFit af = fitAnchoredOnTheCap(classifier_, field, stick_ids, cap, now, pose_, t_, rotation_tests);
  if (af.fit.ok && classifier_.classify(now, field.normal, af.fit.motion * pose_) > 0) {
    stick_ids = stickSet();
    af = fitAnchoredOnTheCap(classifier_, field, stick_ids, cap, now, pose_, t_, rotation_tests);
  }
  std::vector<StickCorrespondence> stick;
  for (int id : stick_ids)
    stick.push_back({pose_ * classifier_.anchor(id), now.position[static_cast<size_t>(id)]});
  std::vector<SlipCorrespondence> slip;
  for (int id : classifier_.withLabel(MarkerLabel::slip)) {
    const size_t i = static_cast<size_t>(id);
    if (before.valid[i] && field.normal_valid[i]) slip.push_back({before.position[i], now.position[i], field.normal[i]});
  }
  ModelEvidence evidence;
  evidence.stick_fit_ok = af.fit.ok;
  evidence.rotation_supported = af.rotation_supported;
  evidence.n_stick = static_cast<int>(stick.size());
  evidence.n_slip = static_cast<int>(slip.size());
  const bool settled = std::all_of(stick_ids.begin(), stick_ids.end(), [&](int id) {
    return classifier_.framesInContact(id) >= t_.stick_hold_frames;
  });
  evidence.slip_fixes_rotation =
      !af.rotation_supported && !slip.empty() &&
      thinStickSetTrusted(evidence.n_stick, !region_developed, settled, options_.min_thin_stick_markers) &&
      stickSlipRotationInformation(stick, slip) >= t_.min_spread_mm * t_.min_spread_mm;
  evidence.stick_set_creeps = region_developed && !af.rotation_supported && !slip.empty() &&
                              evidence.n_stick < options_.min_thin_stick_markers &&
                              slipMarkersOvertake(af.fit.motion, slip, t_.noise_mm, t_.slip_mm);
  step.model = selectModel(evidence, policy);
  if (step.model == PoseModel::kabsch) return af.fit.motion;
  if (step.model == PoseModel::stick_slip) {
    const StickSlipSolution sol = solveStickSlipMotion(stick, slip, af.fit.motion, options_.solver);
    step.model = sol.ok ? PoseModel::stick_slip : PoseModel::centroid;
    step.solver_failed = !sol.ok;
    return sol.ok ? sol.motion : centroid_step;
  }
  // Eq. 16 fails: on a developed contact, macroscopic slip. Unless the
  // markers' own rigid motion since the last frame turns the finger (beyond
  // the tilt gate over the window, where the footprint test cannot decide):
  // then the stick set was too thin to follow a turn about its own line (a
  // plate's edge strip as it tilts), the markers' rigid motion is the
  // finger's, and they stick again.
  // The same holds for a contact too small to declare macroscopic slip, when
  // its markers span an area (a strip cannot fix a turn about itself): while
  // the finger turns, the translation-only fallback would freeze the tilt.
  if (policy != ModelPolicy::adaptive) return centroid_step;
  const bool developed = evidence.n_stick + evidence.n_slip >= options_.min_macro_markers;
  const contact::ContactRegion& region = field.regions[static_cast<size_t>(step.region)];
  const RigidFit rigid = fitConsecutive(members, before, now, t_.robust_mm);
  const Drift drift = rigid.ok ? footprintDrift(field, now, region, rigid.motion * pose_) : Drift{};
  if (rigid.ok && (developed ? !drift.decided : drift.turning && spansArea(members, now))) {
    classifier_.markAllSticking(now, rigid.motion * pose_);
    step.model = PoseModel::kabsch;
    return rigid.motion;
  }
  if (const std::optional<Eigen::Isometry3d> back = restick(field, members, now)) {
    step.model = PoseModel::kabsch;
    step.stuck_again = true;
    return *back;
  }
  if (developed) enterMacroSlip(now, centroid_step);
  return centroid_step;
}

void AdaptivePoseEstimator::enterMacroSlip(const MarkerField& now, const Eigen::Isometry3d& increment) {
  macro_slip_ = true;
  macro_suspect_frames_ = 0;
  macro_frames_ = 0;
  classifier_.markAllSlipping(now, increment * pose_);
}

AdaptivePoseEstimator::Drift AdaptivePoseEstimator::footprintDrift(const contact::ContactField& field,
                                                                   const MarkerField& now,
                                                                   const contact::ContactRegion& region,
                                                                   const Eigen::Isometry3d& next) const {
  Drift out;
  const int window = t_.window_frames;
  if (static_cast<int>(history_.size()) < window) return out;
  const ContactSnapshot& old = history_[history_.size() - static_cast<size_t>(window)];
  const double size = static_cast<double>(region.markers.size());
  out.turning = tiltBetween(next, old.pose) > options_.macro_tilt_gate_deg * kRadPerDeg;
  if (out.turning || std::abs(size - old.region_size) > options_.macro_size_change * old.region_size) return out;
  out.decided = true;
  const CommonFootprints common = commonFootprints(old, field, region.markers, now);
  // Where the footprint would be had it stayed fixed on the finger (carried by
  // the motion, plus the shift rho by which a rolling finger moves its own
  // footprint, contact_cap.hpp), and where it is. Any error of rho counts in
  // the finger's favour: a nearly flat cap (a plate) has so large a radius
  // that no drift can be told from its tilt.
  const Eigen::Vector3d &before = common.before, &after = common.after;
  const Eigen::Isometry3d motion = next * old.pose.inverse();
  const Eigen::AngleAxisd turn(motion.linear());
  const Eigen::Vector2d rho = rollingShift(fitContactCap(field, region.markers, now), turn.angle() * turn.axis());
  out.drift = after - motion * before;
  Eigen::Vector3d travel = after - before;
  out.drift.z() = 0;
  travel.z() = 0;
  out.drift.head<2>() -= rho;
  // A press that deepens moves the footprint centre with no slide, also
  // where the region cannot grow (a plate over the whole pattern: 0.45 mm
  // as it went 0.61 -> 0.74 mm deep). Still decided: when Eq. 16 fails
  // then, the finger slides. (Not an easing press: at a lift-off in slip
  // the drift is the slide.)
  const bool pressing = common.depth_after - common.depth_before > options_.macro_size_change * common.depth_before;
  out.exceeds = !pressing && out.drift.norm() > std::max(t_.macro_drift_mm, options_.macro_drift_ratio * travel.norm()) +
                                                    rho.norm();
  return out;
}

void AdaptivePoseEstimator::checkMacroSlip(const contact::ContactField& field, const MarkerField& now,
                                           const contact::ContactRegion& region, Eigen::Isometry3d& increment) {
  const Drift d = footprintDrift(field, now, region, increment * pose_);
  if (!d.exceeds) {
    macro_suspect_frames_ = 0;
    return;
  }
  // A drift seen in consecutive frames: a footprint jittering because markers
  // come and go is not mistaken for the finger sliding away.
  if (++macro_suspect_frames_ < t_.confirm_frames) return;
  // The finger slides while the markers stay behind: catch up once, then follow the footprint.
  Eigen::Isometry3d catch_up = Eigen::Isometry3d::Identity();
  catch_up.translation() = d.drift;
  increment = catch_up * increment;
  enterMacroSlip(now, increment);
}

bool AdaptivePoseEstimator::stickingAgain(const contact::ContactField& field, const std::vector<int>& members,
                                          const MarkerField& now, std::vector<int>& sticking) const {
  const int window = t_.window_frames;
  if (static_cast<int>(history_.size()) < window) return false;
  const ContactSnapshot& old = history_[history_.size() - static_cast<size_t>(window)];
  int measured = 0;
  for (int id : members) measured += old.markers.valid[static_cast<size_t>(id)] && now.valid[static_cast<size_t>(id)];
  const double needed = std::max<double>(options_.min_thin_stick_markers, options_.restick_fraction * measured);
  sticking = members;
  // A sticking marker stays within the slip threshold of where the finger
  // carries its anchor in every frame (stick_slip_classifier.hpp), so over
  // the window it may depart from a rigid motion by twice that.
  const RigidFit fit = fitConsensus(sticking, old.markers, now, t_.robust_mm, 2.0 * t_.slip_mm,
                                    static_cast<size_t>(std::ceil(needed)));
  if (!fit.ok || static_cast<double>(sticking.size()) < needed) return false;
  std::vector<Eigen::Vector3d> kept;  // all valid in `now` (fitConsensus keeps only those)
  for (int id : sticking) kept.push_back(now.position[static_cast<size_t>(id)]);
  const double extent = kept.size() >= 3 ? planarSpread(kept).x() : 0.0;  // as spansArea, computed once
  if (extent < t_.min_spread_mm) return false;
  // Rolling moves the footprint over the finger by rho (contact_cap.hpp), but
  // only a turn beyond what the trim lets a non-rigid set fake (slip threshold
  // over the consensus's smaller extent) is credited: saturated markers of a
  // slide drift that much and would explain the slide away as a roll.
  const Eigen::AngleAxisd turn(fit.motion.linear());
  const double vouched = std::max(0.0, turn.angle() - t_.slip_mm / extent);
  const CommonFootprints common = commonFootprints(old, field, members, now);
  const Eigen::Vector3d &before = common.before, &after = common.after;
  const Eigen::Vector2d rho =
      vouched > 0 ? rollingShift(fitContactCap(field, members, now), vouched * turn.axis()) : Eigen::Vector2d::Zero();
  const Eigen::Vector2d lag = (after - fit.motion * before).head<2>();
  // Distance from the lag to the segment from no shift to the full rolling shift.
  const double along = rho.squaredNorm() > 0 ? std::clamp(lag.dot(rho) / rho.squaredNorm(), 0.0, 1.0) : 0.0;
  return (lag - along * rho).norm() < t_.macro_exit_lag_mm + options_.macro_drift_ratio * rho.norm();
}

std::optional<Eigen::Isometry3d> AdaptivePoseEstimator::restick(const contact::ContactField& field,
                                                                const std::vector<int>& members,
                                                                const MarkerField& now) {
  std::vector<int> sticking;
  if (!stickingAgain(field, members, now, sticking)) return std::nullopt;
  const RigidFit step = fitConsecutive(sticking, history_.back().markers, now, t_.robust_mm);
  if (!step.ok) return std::nullopt;
  classifier_.markSticking(sticking, now, step.motion * pose_);
  return step.motion;
}

void AdaptivePoseEstimator::remember(const contact::ContactField& field, const MarkerField& now,
                                     const contact::ContactRegion& region) {
  history_.push_back({now, field.displacement, region.cut_mm, region.markers, region.footprint_centre, pose_,
                      static_cast<double>(region.markers.size())});
  while (static_cast<int>(history_.size()) > t_.window_frames) history_.pop_front();
}

bool AdaptivePoseEstimator::spansArea(const std::vector<int>& members, const MarkerField& now) const {
  std::vector<Eigen::Vector3d> p;
  for (int id : members)
    if (now.valid[static_cast<size_t>(id)]) p.push_back(now.position[static_cast<size_t>(id)]);
  return p.size() >= 3 && planarSpread(p).x() >= t_.min_spread_mm;
}

Eigen::Isometry3d AdaptivePoseEstimator::centroidStep(const contact::ContactField& field, const std::vector<int>& members,
                                                      const MarkerField& now) const {
  if (!macro_slip_ && static_cast<int>(members.size()) < options_.min_macro_markers) {
    // A small contact's footprint is too coarse: its markers' mean motion.
    const RigidFit fit = fitConsecutive(members, history_.back().markers, now, 0, true);
    if (fit.ok) return fit.motion;
  }
  const CommonFootprints common = commonFootprints(history_.back(), field, members, now);
  return centroidMotion(common.before, common.after);
}

PoseStep AdaptivePoseEstimator::update(const contact::ContactField& field, const MarkerField& measured,
                                       const SensorSelf& self) {
  if (!field.in_contact || field.status != contact::ContactFieldStatus::ok) {
    reset();
    return {};
  }
  // Markers the contact stage graded below its confidence cut are not
  // measured this frame (contact_analyzer.hpp): no fit, label or anchor uses them.
  const MarkerField trusted = field.low_confidence > 0 ? contact::trustedMarkers(measured, field) : MarkerField{};
  const MarkerField& now = field.low_confidence > 0 ? trusted : measured;
  t_ = deriveThresholds(options_, self);
  if (options_.policy == ModelPolicy::weighted) return weighted_.update(field, now, t_);
  classifier_.setOptions({t_.slip_mm, t_.stick_hold_frames});
  if (!active_) {
    PoseStep first = start(field, now);
    first.thresholds = t_;
    return first;
  }

  const int tracked = trackedRegion(field);
  if (tracked < 0) {  // the finger tracked lifted while another stays: its contact ended, a new one begins
    reset();
    PoseStep first = start(field, now);
    first.thresholds = t_;
    return first;
  }
  PoseStep step;
  step.active = true;
  step.thresholds = t_;
  step.onset_centroid = c0_;
  step.region = tracked;
  const contact::ContactRegion& region = field.regions[static_cast<size_t>(step.region)];
  classifier_.retain(region.markers, now);

  Eigen::Isometry3d increment = solveIncrement(field, now, step);
  if (options_.policy == ModelPolicy::adaptive && !macro_slip_ && !step.stuck_again &&
      static_cast<int>(region.markers.size()) >= options_.min_macro_markers)
    checkMacroSlip(field, now, region, increment);

  increment = limitIncrement(increment, pose_ * c0_, t_.max_step_mm, t_.max_step_rad, step.step_limited);
  pose_ = increment * pose_;
  classifier_.anchorNew(region.markers, now, pose_);

  remember(field, now, region);
  reportUncertainty(now, increment, step);

  step.n_stick = static_cast<int>(classifier_.withLabel(MarkerLabel::stick).size());
  step.n_slip = static_cast<int>(classifier_.withLabel(MarkerLabel::slip).size());
  if (macro_slip_ || (step.n_stick == 0 && step.n_slip > 0)) step.state = ContactState::slip;
  else step.state = step.n_slip > 0 ? ContactState::partial_slip : ContactState::stick;
  step.increment = increment;
  step.pose = pose_;
  return step;
}

void AdaptivePoseEstimator::reportUncertainty(const MarkerField& now, const Eigen::Isometry3d& increment,
                                              PoseStep& step) {
  step.labels = classifier_.labels();
  step.stick_probability.assign(step.labels.size(), 0.0);
  std::vector<Eigen::Vector3d> points;
  std::vector<double> weights;
  double weighted_square = 0;
  const bool footprint_carries = macro_slip_ || step.model == PoseModel::centroid;
  for (size_t i = 0; i < step.labels.size(); ++i) {
    if (step.labels[i] == MarkerLabel::outside) continue;
    const double p = contact::stickProbability(classifier_.lastDrift(static_cast<int>(i)), t_.slip_mm, t_.max_step_mm);
    step.stick_probability[i] = p;
    // A marker anchored this frame has told nothing yet about the motion.
    if (footprint_carries || step.labels[i] != MarkerLabel::stick || classifier_.framesInContact(static_cast<int>(i)) == 0)
      continue;
    points.push_back(now.position[i]);
    weights.push_back(p);
    weighted_square += p * (now.position[i] - pose_ * classifier_.anchor(static_cast<int>(i))).squaredNorm();
  }
  double total = 0;
  for (double w : weights) total += w;
  // Per-axis scatter of the stick set about the fit (three axes per marker), never below the noise.
  const double sigma = std::max(t_.noise_mm, total > 0 ? std::sqrt(weighted_square / (3 * total)) : 0.0);
  if (step.onset) return;  // the identity, known exactly: sd 0
  uncertainty_.add(stickInformation(points, weights, pose_ * c0_, sigma, t_.slip_mm), increment,
                    t_.frame_s);
  step.sd = uncertainty_.sd();
}

}  // namespace onetip::pose
