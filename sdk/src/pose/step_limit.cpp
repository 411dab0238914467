#include "pose/step_limit.hpp"

#include <algorithm>

namespace onetip::pose {

Eigen::Isometry3d limitIncrement(const Eigen::Isometry3d& increment, const Eigen::Vector3d& c, double max_step_mm,
                                 double max_step_rad, bool& limited) {
  const Eigen::Vector3d d = increment * c - c;
  const Eigen::AngleAxisd aa(increment.linear());
  double s = 1;
  if (d.norm() > max_step_mm) s = std::min(s, max_step_mm / d.norm());
  if (aa.angle() > max_step_rad) s = std::min(s, max_step_rad / aa.angle());
  limited = s < 1;
  if (!limited) return increment;
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = Eigen::AngleAxisd(s * aa.angle(), aa.axis()).toRotationMatrix();
  out.translation() = c + s * d - out.linear() * c;
  return out;
}

}  // namespace onetip::pose
