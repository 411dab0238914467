#include "sim/ground_truth.hpp"

#include "core/rotation.hpp"

namespace onetip::sim {

void GroundTruthPose::update(GroundTruthFrame& f, const MarkerField& rest) {
  double max_modulus = 0, max_normal = 0;
  for (int i = 0; i < rest.size(); ++i) {
    const Eigen::Vector3d u = f.markers.position[static_cast<size_t>(i)] - rest.position[static_cast<size_t>(i)];
    max_modulus = std::max(max_modulus, u.norm());
    max_normal = std::max(max_normal, std::abs(u.z()));
  }
  f.in_contact = max_modulus > threshold_;
  if (!f.in_contact || f.indenter_poses.empty()) {
    active_ = false;
    f.input = Input6{};
    return;
  }
  if (!active_) {
    active_ = true;
    onset_pose_ = f.indenter_poses.front();
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int n = 0;
    for (int i = 0; i < rest.size(); ++i) {
      const Eigen::Vector3d u = f.markers.position[static_cast<size_t>(i)] - rest.position[static_cast<size_t>(i)];
      if (u.norm() >= fraction_ * max_normal) {
        sum += rest.position[static_cast<size_t>(i)];
        ++n;
      }
    }
    c0_ = n > 0 ? Eigen::Vector3d(sum / n) : Eigen::Vector3d::Zero();
  }
  const Eigen::Isometry3d T = f.indenter_poses.front() * onset_pose_.inverse();
  f.input = input6FromMotion(T, c0_);
}

}  // namespace onetip::sim
