#include "input/pose_accumulator.hpp"

#include "core/rotation.hpp"

namespace onetip::input {

void PoseAccumulator::reset(const Eigen::Vector3d& onset_centroid, double marker_depth_mm) {
  reference_ = onset_centroid - marker_depth_mm * Eigen::Vector3d::UnitZ();
  motion_ = Eigen::Isometry3d::Identity();
  euler_sum_ = Input6{};
}

void PoseAccumulator::add(const Eigen::Isometry3d& increment) {
  motion_ = increment * motion_;
  const auto step = input6FromMotion(increment, reference_).asArray();
  auto sum = euler_sum_.asArray();
  for (size_t k = 0; k < sum.size(); ++k) sum[k] += step[k];
  euler_sum_ = Input6::fromArray(sum);
}

Input6 PoseAccumulator::composed() const { return input6FromMotion(motion_, reference_); }

}  // namespace onetip::input
