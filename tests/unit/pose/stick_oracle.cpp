#include "stick_oracle.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "campaign_score.hpp"
#include "contact/surface_normals.hpp"
#include "core/rotation.hpp"
#include "observable_truth.hpp"
#include "pose/pose_uncertainty.hpp"
#include "pose/weighted_increment.hpp"
#include "sliding_surface.hpp"

namespace onetip::poseval {

namespace {

// The footprint's move: the centroid of the markers that touch the finger in
// both frames (a set that shrinks or grows would move its centroid without
// any slide), their surface points (S, mm).
template <typename Touches>
std::optional<pose::FootprintEvidence> commonFootprint(const MarkerField& before, const MarkerField& now,
                                                       const Touches& touches, const Eigen::Vector3d& depth,
                                                       double noise_mm) {
  Eigen::Vector3d then = Eigen::Vector3d::Zero(), seen = Eigen::Vector3d::Zero();
  int n = 0;
  for (size_t i = 0; i < static_cast<size_t>(now.size()); ++i)
    if (touches(i) && before.valid[i]) {
      then += before.position[i] + depth;
      seen += now.position[i] + depth;
      ++n;
    }
  if (n == 0) return std::nullopt;
  return pose::FootprintEvidence{then / n, seen / n, noise_mm};
}

}  // namespace

void applyStickOracle(const Recording& rec, std::vector<ReplayFrame>& frames, const StickOracleOptions& options) {
  const pose::PoseUncertaintyOptions prior;
  const Eigen::Vector3d depth(0, 0, rec.marker_depth_mm);  // a marker's surface point lies d above it (0003)
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();     // the finger since onset (S, mm)
  Eigen::Isometry3d last_increment = Eigen::Isometry3d::Identity();  // T_{k-1} T_{k-2}^-1
  std::map<size_t, Eigen::Vector3d> anchors;  // marker -> its surface point on the finger (onset coordinates)
  std::set<size_t> held;  // OracleLabels::self: the markers labelled for the next frame
  std::vector<Eigen::Vector3d> normal;
  std::vector<std::uint8_t> normal_valid;
  for (size_t k = 0; k < frames.size() && k < rec.truth.size(); ++k) {
    const sim::GroundTruthFrame& truth = rec.truth[k];
    const MarkerField& now = rec.frames[k];
    ReplayFrame& f = frames[k];
    const std::vector<std::uint8_t> estimated = f.stick;
    f.contact = truth.in_contact;
    f.raw = f.composed = Input6{};
    f.stick.assign(static_cast<size_t>(now.size()), 0);
    if (!truth.in_contact) continue;
    const bool onset = k == 0 || !frames[k - 1].gt_contact || f.gt_c0 != frames[k - 1].gt_c0;  // the truth's onset
    if (onset) {
      T = Eigen::Isometry3d::Identity();
      last_increment = Eigen::Isometry3d::Identity();
      anchors.clear();
    }
    const Eigen::Isometry3d T_before = T;
    std::set<size_t> slipped;  // carrying markers the reweighting let slip this frame
    const Eigen::Vector3d& c0 = f.gt_c0;
    const auto ours = [&](size_t i) {
      return now.valid[i] && f.gt_contact_markers[i] && (f.gt_followed.empty() || f.gt_followed[i]);
    };
    const auto sticks = [&](size_t i) {
      const bool truly = ours(i) && trulySticks(f, i);
      const bool labelled = now.valid[i] && i < estimated.size() && estimated[i];
      switch (options.labels) {
        case OracleLabels::truth: return truly;
        case OracleLabels::estimate: return labelled;
        case OracleLabels::estimate_true: return labelled && truly;
        case OracleLabels::estimate_touching: return labelled && ours(i);
        case OracleLabels::none: return false;
        case OracleLabels::self: return ours(i) && (onset || held.count(i) > 0);
      }
      return false;
    };
    std::vector<size_t> sticking;
    for (size_t i = 0; i < static_cast<size_t>(now.size()); ++i)
      if (sticks(i)) sticking.push_back(i);
    if (onset) held = std::set<size_t>(sticking.begin(), sticking.end());
    if (!onset && noMarkerSticksThrough(frames[k - 1], f)) {  // the observable truth's move, the turn held
      const ReplayFrame& prev = frames[k - 1];
      if (f.gt_footprint_valid && prev.gt_footprint_valid)
        T.translation().head<2>() += f.gt_footprint - prev.gt_footprint;
      T.translation().z() -= f.gt.dz - prev.gt.dz;
    } else if (!onset) {
      const MarkerField& before = rec.frames[k - 1];
      const ReplayFrame& prev = frames[k - 1];
      contact::gridSurfaceNormals(now, normal, normal_valid);
      pose::WeightedIncrementProblem problem;
      problem.centre = T * c0;
      const double frame_s = std::max(truth.t - rec.truth[k - 1].t, 1e-4);
      problem.prior_turn_sd_rad = prior.unseen_turn_deg_per_sqrt_s * kRadPerDeg * std::sqrt(frame_s);
      problem.prior_slide_sd_mm = prior.unseen_slide_mm_per_sqrt_s * std::sqrt(frame_s);
      if (options.prior_rate_tau_s > 0) {  // the last increment again, about this frame's centre, decayed
        const double decay = std::exp(-frame_s / options.prior_rate_tau_s);
        const Eigen::AngleAxisd turn(last_increment.linear());
        problem.prior_turn_rad = decay * turn.angle() * turn.axis();
        problem.prior_slide_mm = decay * (last_increment * problem.centre - problem.centre);
      }
      int stuck = 0;
      std::vector<size_t> ids;     // per problem marker: its id
      std::vector<bool> carried;   // ... whether it carried the finger as labelled
      std::vector<bool> slides;  // per problem marker: whether its normal residual takes slidingSurfaceSd
      for (size_t i = 0; i < static_cast<size_t>(now.size()); ++i) {
        if (!before.valid[i] || !(ours(i) || sticks(i))) continue;
        const auto a = anchors.find(i);
        const bool carries = sticks(i) && a != anchors.end();
        if (!carries && (!normal_valid[i] || !options.slip_normals)) continue;
        pose::WeightedMarker m;
        m.anchor = carries ? Eigen::Vector3d(T * a->second) : Eigen::Vector3d(before.position[i] + depth);
        m.before = before.position[i] + depth;
        m.now = now.position[i] + depth;
        m.normal = normal_valid[i] ? normal[i] : Eigen::Vector3d::Zero();
        m.weight = carries ? 1 : 0;
        m.sd_mm = std::sqrt(2.0) * options.noise_mm;
        problem.markers.push_back(m);
        slides.push_back(!carries && options.sliding_model_error);
        ids.push_back(i);
        carried.push_back(carries);
        stuck += carries ? 1 : 0;
      }
      // A sliding marker's normal residual carries its slide's model error (slidingSurfaceSd): the slide is
      // first predicted by the last increment, then taken from this frame's solve, which is solved again.
      const auto slidesBy = [&](const Eigen::Isometry3d& increment) {
        for (size_t j = 0; j < problem.markers.size(); ++j) {
          pose::WeightedMarker& m = problem.markers[j];
          if (slides[j])
            m.surface_sd_mm = slidingSurfaceSd(m.sd_mm, increment * m.before - m.now, m.normal,
                                                     prior.relative_increment_error);
        }
      };
      const auto touched_both = [&](size_t i) {
        return ours(i) && i < prev.gt_contact_markers.size() && prev.gt_contact_markers[i];
      };
      if (stuck == 0) problem.footprint = commonFootprint(before, now, touched_both, depth, options.noise_mm);
      // Without that error (the noise alone) one solve, as decision record 0018 measured it.
      slidesBy(last_increment);
      Eigen::Isometry3d increment = pose::solveWeightedIncrement(problem, Eigen::Isometry3d::Identity(), nullptr, 5);
      if (options.sliding_model_error) {
        slidesBy(increment);
        increment = pose::solveWeightedIncrement(problem, increment, nullptr, 5);
      }
      if (options.reweight) {  // every marker its cheapest case; a carrying marker that slips is re-anchored
        increment = pose::solveByReweighting(problem, increment);
        const auto carries_now = [](const pose::WeightedMarker& m) { return m.weight >= 0.5; };
        if (problem.footprint && std::any_of(problem.markers.begin(), problem.markers.end(), carries_now)) {
          problem.footprint.reset();  // the footprint carries the slide only while no marker sticks
          increment = pose::solveByReweighting(problem, increment);
        }
        for (size_t j = 0; j < problem.markers.size(); ++j)
          if (carried[j] && problem.markers[j].weight < 0.5) slipped.insert(ids[j]);
        held.clear();  // the self labels of the next frame: every marker that carried or moved with the finger
        for (size_t j = 0; j < problem.markers.size(); ++j)
          if (carried[j] || problem.markers[j].weight >= 0.5) held.insert(ids[j]);
      }
      T = increment * T;
    }
    last_increment = T * T_before.inverse();
    std::map<size_t, Eigen::Vector3d> kept;
    for (size_t i : sticking) {
      if (slipped.count(i)) {  // it sticks again where it now is
        kept[i] = T.inverse() * (now.position[i] + depth);
        continue;
      }
      const auto a = anchors.find(i);
      kept[i] = a != anchors.end() ? a->second : Eigen::Vector3d(T.inverse() * (now.position[i] + depth));
      f.stick[i] = 1;
    }
    anchors.swap(kept);
    f.raw = f.composed = input6FromMotion(T, c0);
  }
}

}  // namespace onetip::poseval
