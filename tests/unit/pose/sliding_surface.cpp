#include "sliding_surface.hpp"

#include <cmath>

namespace onetip::poseval {

double slidingSurfaceSd(double noise_sd_mm, const Eigen::Vector3d& slide_mm, const Eigen::Vector3d& normal,
                        double relative_error) {
  const double departure = relative_error * (slide_mm - slide_mm.dot(normal) * normal).norm();
  return std::sqrt(noise_sd_mm * noise_sd_mm + departure * departure);
}

}  // namespace onetip::poseval
