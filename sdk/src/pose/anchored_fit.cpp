#include "pose/anchored_fit.hpp"

#include <algorithm>
#include <cmath>

namespace onetip::pose {

bool thinSetTurnEvidenced(const RigidFit& fit, const std::vector<Eigen::Vector3d>& from,
                          const std::vector<Eigen::Vector3d>& to, const PlanarExtent& extent, double noise_mm,
                          const RotationTests& tests) {
  if (!fit.ok || from.size() < 3 || extent.spread.x() <= 0) return false;
  for (size_t i = 0; i < from.size(); ++i)
    if ((fit.motion * from[i] - to[i]).norm() > tests.thin_rigidity_sigmas * noise_mm) return false;
  const Eigen::AngleAxisd turn(fit.motion.linear());
  const double about_line = std::abs((turn.angle() * turn.axis()).head<2>().dot(extent.major_axis));
  const double sigma = std::sqrt(2.0) * noise_mm / (extent.spread.x() * std::sqrt(static_cast<double>(from.size())));
  return about_line >= tests.thin_turn_significance * sigma;
}

AnchoredFit fitAnchored(const contact::StickSlipClassifier& classifier, const contact::ContactField& field,
                        std::vector<int>& ids, const MarkerField& now, const Eigen::Isometry3d& pose,
                        const EstimatorThresholds& t, const RotationTests& tests) {
  std::vector<Eigen::Vector3d> from, to, relax;
  for (int id : ids) {
    const size_t i = static_cast<size_t>(id);
    from.push_back(pose * classifier.anchor(id));
    to.push_back(now.position[i]);
    // A marker relaxes along minus its tangential displacement.
    const Eigen::Vector3d& u = field.displacement[i];
    const Eigen::Vector3d& n = field.normal[i];
    const Eigen::Vector3d tangential = u - u.dot(n) * n;
    const double size = tangential.norm();
    relax.push_back(size > 1e-9 ? Eigen::Vector3d(-tangential / size) : Eigen::Vector3d::Zero());
  }
  const TrimmedFit trimmed = fitRigidMotionTrimmed(from, to, relax, t.robust_mm, t.slip_mm);
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
  const PlanarExtent extent = planarExtent(from);
  const Eigen::Vector2d& spread = extent.spread;
  const auto significant = [&](const RigidFit& fit, double lever) {
    const double sigma = std::sqrt(2.0) * t.noise_mm / (lever * std::sqrt(static_cast<double>(from.size())));
    return fit.ok && Eigen::AngleAxisd(fit.motion.linear()).angle() >= tests.significance * sigma;
  };
  AnchoredFit out;
  if (trimmed.fit.ok && spread.x() >= t.min_spread_mm && significant(trimmed.fit, spread.x())) {
    out.fit = trimmed.fit;
    out.rotation_supported = true;
    return out;
  }
  // A set narrower than the min spread: a general rotation when it moves
  // rigidly and its turn about its own line is significant.
  if (trimmed.fit.ok && spread.x() < t.min_spread_mm &&
      thinSetTurnEvidenced(trimmed.fit, from, to, extent, t.noise_mm, tests)) {
    out.fit = trimmed.fit;
    out.rotation_supported = true;
    return out;
  }
  if (spread.x() < t.min_spread_mm && spread.y() >= t.min_spread_mm) {
    const RigidFit yaw = fitRotationAboutZ(from, to);
    if (significant(yaw, spread.y())) {
      out.fit = yaw;
      return out;
    }
  }
  out.fit = fitTranslation(from, to);
  return out;
}

AnchoredFit fitAnchoredOnTheCap(const contact::StickSlipClassifier& classifier, const contact::ContactField& field,
                                std::vector<int>& ids, const std::vector<std::uint8_t>& cap, const MarkerField& now,
                                const Eigen::Isometry3d& pose, const EstimatorThresholds& t,
                                const RotationTests& tests) {
  std::vector<int> on_cap;
  for (int id : ids)
    if (static_cast<size_t>(id) < cap.size() && cap[static_cast<size_t>(id)]) on_cap.push_back(id);
  const AnchoredFit fit = fitAnchored(classifier, field, ids, now, pose, t, tests);
  const auto kept = std::count_if(on_cap.begin(), on_cap.end(),
                                  [&](int id) { return std::find(ids.begin(), ids.end(), id) != ids.end(); });
  if (2 * static_cast<size_t>(kept) >= on_cap.size()) return fit;
  ids = on_cap;
  return fitAnchored(classifier, field, ids, now, pose, t, tests);
}

RigidFit fitConsecutive(const std::vector<int>& members, const MarkerField& before, const MarkerField& now,
                        double robust_mm, bool translation_only) {
  std::vector<Eigen::Vector3d> from, to;
  for (int id : members) {
    const size_t i = static_cast<size_t>(id);
    if (!before.valid[i] || !now.valid[i]) continue;
    from.push_back(before.position[i]);
    to.push_back(now.position[i]);
  }
  if (translation_only) return fitTranslation(from, to);
  return robust_mm > 0 ? fitRigidMotionRobust(from, to, robust_mm) : fitRigidMotion(from, to);
}

RigidFit fitConsensus(std::vector<int>& members, const MarkerField& before, const MarkerField& now, double scale_mm,
                      double trim_mm, size_t min_kept) {
  std::vector<int> ids;
  std::vector<Eigen::Vector3d> from, to;
  for (int id : members) {
    const size_t i = static_cast<size_t>(id);
    if (!before.valid[i] || !now.valid[i]) continue;
    ids.push_back(id);
    from.push_back(before.position[i]);
    to.push_back(now.position[i]);
  }
  members.clear();
  const TrimmedFit trimmed = fitRigidMotionTrimmed(from, to, {}, scale_mm, trim_mm, min_kept);
  if (!trimmed.fit.ok || !trimmed.within_trim) return RigidFit{};
  for (size_t k = 0; k < ids.size(); ++k)
    if (trimmed.inlier[k]) members.push_back(ids[k]);
  return trimmed.fit;
}

}  // namespace onetip::pose
