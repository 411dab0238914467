#include "sim/ground_truth.hpp"

#include "core/rotation.hpp"

namespace onetip::sim {

void GroundTruthPose::update(GroundTruthFrame& f, const MarkerField& rest, const MarkerField& deformed) {
  double max_modulus = 0, max_normal = 0;
  for (int i = 0; i < rest.size(); ++i) {
    const Eigen::Vector3d u = deformed.position[static_cast<size_t>(i)] - rest.position[static_cast<size_t>(i)];
    max_modulus = std::max(max_modulus, u.norm());
    max_normal = std::max(max_normal, std::abs(u.z()));
  }
  f.in_contact = max_modulus > threshold_;
  if (!f.in_contact || f.indenter_poses.empty()) {
    active_ = false;
    f.input = Input6{};
    f.onset_centroid = Eigen::Vector3d::Zero();
    return;
  }
  const auto touching = [&](int k) {
    return static_cast<size_t>(k) < f.indenter_nodes.size() ? f.indenter_nodes[static_cast<size_t>(k)] : 0;
  };
  if (active_ && !f.indenter_nodes.empty() && touching(followed_) == 0) active_ = false;  // it lifted, another stays
  if (!active_) {
    active_ = true;
    followed_ = 0;
    for (int k = 1; k < static_cast<int>(f.indenter_poses.size()); ++k)
      if (touching(k) > touching(followed_)) followed_ = k;
    onset_pose_ = f.indenter_poses[static_cast<size_t>(followed_)];
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int n = 0;
    for (int i = 0; i < rest.size(); ++i) {
      const Eigen::Vector3d u = deformed.position[static_cast<size_t>(i)] - rest.position[static_cast<size_t>(i)];
      if (u.norm() >= fraction_ * max_normal) {
        sum += rest.position[static_cast<size_t>(i)];
        ++n;
      }
    }
    c0_ = n > 0 ? Eigen::Vector3d(sum / n) : Eigen::Vector3d::Zero();
  }
  f.followed = followed_;
  f.onset_centroid = c0_;
  const Eigen::Isometry3d T = f.indenter_poses[static_cast<size_t>(followed_)] * onset_pose_.inverse();
  f.input = input6FromMotion(T, c0_);
}

}  // namespace onetip::sim
