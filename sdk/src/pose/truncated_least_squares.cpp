#include "pose/truncated_least_squares.hpp"

#include <algorithm>
#include <cmath>

namespace onetip::pose {

double gncInitialMu(double max_r2, double cbar2) {
  if (max_r2 <= cbar2) return 0.0;
  return cbar2 / (2.0 * max_r2 - cbar2);
}

double gncWeight(double r2, double cbar2, double mu) {
  if (mu <= 0) return 1.0;
  if (r2 <= mu / (mu + 1.0) * cbar2) return 1.0;
  if (r2 >= (mu + 1.0) / mu * cbar2) return 0.0;
  return std::clamp(std::sqrt(cbar2 * mu * (mu + 1.0) / r2) - mu, 0.0, 1.0);
}

bool gncWeightsBinary(const std::vector<double>& weights, double tolerance) {
  return std::all_of(weights.begin(), weights.end(), [&](double w) { return w <= tolerance || w >= 1.0 - tolerance; });
}

}  // namespace onetip::pose
