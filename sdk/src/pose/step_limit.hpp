// pose/step_limit.hpp — safety: one frame's increment is limited to
// max_step_mm of motion of the finger's reference point c (S, mm) and
// max_step_rad of rotation (from the fastest finger motion followed,
// max_speed_mm_s and max_rate_deg_s times the frame interval), scaled down
// along its own screw with its direction kept.
#pragma once

#include <Eigen/Geometry>

namespace onetip::pose {

Eigen::Isometry3d limitIncrement(const Eigen::Isometry3d& increment, const Eigen::Vector3d& c, double max_step_mm,
                                 double max_step_rad, bool& limited);

}  // namespace onetip::pose
