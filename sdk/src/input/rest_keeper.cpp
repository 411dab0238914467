#include "input/rest_keeper.hpp"

#include <algorithm>
#include <cmath>

#include "core/option_checks.hpp"
#include "pose/rigid_fit.hpp"

namespace onetip::input {

void RestKeeperOptions::validate() const {
  requireInRange("rest keeper: move_sigmas", move_sigmas, 3, 1000);
  requireInRange("rest keeper: move_report_mm", move_report_mm, 0, 10, "mm");
  requireInRange("rest keeper: drift_sigmas", drift_sigmas, 1, 100);
  requireInRange("rest keeper: drift_time_s", drift_time_s, 0.1, 3600, "s");
  requireInRange("rest keeper: hidden_s", hidden_s, 0.1, 3600, "s");
}

RestKeeper::RestKeeper(RestKeeperOptions options) : options_(options) { options_.validate(); }

void RestKeeper::reset() {
  reference_ = MarkerField{};
  rest_ = MarkerField{};
  have_t_ = false;
  missing_since_.clear();
  reported_.clear();
}

namespace {

bool sameField(const MarkerField& a, const MarkerField& b) {
  return a.rows == b.rows && a.cols == b.cols && a.valid == b.valid && a.position == b.position;
}

}  // namespace

bool RestKeeper::alignWholeField(const MarkerField& now, double noise_mm, double contact_threshold_mm,
                                 RestUpdate& out) {
  std::vector<Eigen::Vector3d> from, to;
  for (size_t i = 0; i < now.position.size(); ++i)
    if (now.valid[i] && rest_.valid[i]) {
      from.push_back(rest_.position[i]);
      to.push_back(now.position[i]);
    }
  if (from.size() < 3) return false;
  const double bound = options_.move_sigmas * noise_mm;
  double largest = 0;
  for (size_t i = 0; i < from.size(); ++i) largest = std::max(largest, (to[i] - from[i]).norm());
  if (largest <= bound) return false;  // nothing moved beyond the noise: drift following is enough
  const pose::RigidFit g = pose::fitRigidMotionRobust(from, to, contact_threshold_mm / 4, 3);
  if (!g.ok) return false;
  const double explained = contact_threshold_mm / 2;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double moved = 0;
  for (size_t i = 0; i < from.size(); ++i) {
    if ((g.motion * from[i] - to[i]).norm() > explained) return false;  // a touch: its dimple is left over
    moved = std::max(moved, (g.motion * from[i] - from[i]).norm());
    centroid += from[i];
  }
  if (moved <= bound) return false;  // a finger's G: the far markers stayed, the rest stays too
  centroid /= static_cast<double>(from.size());
  // Into or out of the pad at the field's centre: a flat plate pressed over the whole pattern looks so.
  if (std::abs((g.motion * centroid - centroid).z()) > bound) return false;
  for (size_t i = 0; i < rest_.position.size(); ++i)
    if (rest_.valid[i]) rest_.position[i] = g.motion * rest_.position[i];
  out.moved = moved >= options_.move_report_mm;
  out.moved_mm = moved;
  return true;
}

void RestKeeper::followDrift(const MarkerField& now, double noise_mm, double dt) {
  const double gain = std::clamp(dt / options_.drift_time_s, 0.0, 1.0);
  const double bound = options_.drift_sigmas * noise_mm;
  for (size_t i = 0; i < now.position.size(); ++i) {
    if (!now.valid[i] || !rest_.valid[i]) continue;
    const Eigen::Vector3d e = now.position[i] - rest_.position[i];
    if (e.norm() < bound) rest_.position[i] += gain * e;
  }
}

void RestKeeper::trackHidden(const MarkerField& now, double t, RestUpdate& out) {
  for (size_t i = 0; i < now.position.size(); ++i) {
    if (!rest_.valid[i]) continue;
    if (now.valid[i]) {
      missing_since_[i] = -1;
      reported_[i] = 0;
      continue;
    }
    if (missing_since_[i] < 0) missing_since_[i] = t;
    if (!reported_[i] && t - missing_since_[i] >= options_.hidden_s) {
      reported_[i] = 1;
      out.hidden.push_back(static_cast<int>(i));
    }
  }
}

RestUpdate RestKeeper::update(const MarkerField& now, const MarkerField& reference, bool was_in_contact,
                              double noise_mm, double contact_threshold_mm, double t) {
  RestUpdate out;
  if (!sameField(reference, reference_)) {
    reference_ = reference;
    rest_ = reference;
    have_t_ = false;
    missing_since_.assign(reference.position.size(), -1);
    reported_.assign(reference.position.size(), 0);
    // A marker the rest state itself lacks was hidden before the sensor started: named with the first frame.
    for (size_t i = 0; i < reference.position.size(); ++i)
      if (!reference.valid[i]) out.hidden.push_back(static_cast<int>(i));
  }
  if (now.size() != rest_.size()) return out;  // the caller refuses a grid mismatch
  const double dt = have_t_ ? std::max(0.0, t - last_t_) : 0.0;
  have_t_ = true;
  last_t_ = t;
  trackHidden(now, t, out);
  if (was_in_contact) return out;
  if (!alignWholeField(now, noise_mm, contact_threshold_mm, out)) followDrift(now, noise_mm, dt);
  return out;
}

std::string describeHidden(const std::vector<int>& ids) {
  std::string s = "markers hidden (a damaged or dirty pad?), ids";
  for (size_t k = 0; k < ids.size() && k < 20; ++k) s += (k ? ", " : " ") + std::to_string(ids[k]);
  if (ids.size() > 20) s += " and " + std::to_string(ids.size() - 20) + " more";
  return s + ": tracking goes on without them";
}

}  // namespace onetip::input
