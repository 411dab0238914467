#include "pose/stick_set_creep.hpp"

#include <cmath>

namespace onetip::pose {

bool slipMarkersOvertake(const Eigen::Isometry3d& stick_motion, const std::vector<SlipCorrespondence>& slip,
                         double noise_mm, double lead_mm) {
  const double floor = 3.0 * std::sqrt(2.0) * noise_mm;
  for (const SlipCorrespondence& c : slip) {
    const Eigen::Vector3d carried = stick_motion * c.from;
    const Eigen::Vector2d motion = (carried - c.from).head<2>();
    if (motion.norm() <= floor) continue;
    if ((c.to - carried).head<2>().dot(motion.normalized()) > lead_mm) return true;
  }
  return false;
}

}  // namespace onetip::pose
