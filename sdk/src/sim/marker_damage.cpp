#include "sim/marker_damage.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "core/error.hpp"
#include "core/option_checks.hpp"
#include "sim/image_effects.hpp"

namespace onetip::sim {

std::vector<int> MarkerDamageOptions::hiddenIds(const MarkerPattern& pattern) const {
  const int n = pattern.count();
  std::vector<std::uint8_t> hidden(static_cast<size_t>(n), 0);
  for (int id : ids) {
    if (id < 0 || id >= n)
      throw InputError("damage: ids: marker " + std::to_string(id) + " is not in the " + std::to_string(pattern.rows) +
                       " x " + std::to_string(pattern.cols) + " pattern");
    hidden[static_cast<size_t>(id)] = 1;
  }
  std::vector<int> others;
  for (int id = 0; id < n; ++id)
    if (!hidden[static_cast<size_t>(id)]) others.push_back(id);
  std::mt19937 rng(seed);
  std::shuffle(others.begin(), others.end(), rng);
  const auto extra = std::min(others.size(), static_cast<size_t>(std::lround(fraction * n)));
  for (size_t i = 0; i < extra; ++i) hidden[static_cast<size_t>(others[i])] = 1;
  std::vector<int> out;
  for (int id = 0; id < n; ++id)
    if (hidden[static_cast<size_t>(id)]) out.push_back(id);
  return out;
}

void MarkerDamageOptions::validate() const {
  requireInRange("damage: fraction", fraction, 0, 0.5);
  requireInRange("damage: radius", radius, 0.2, 0.6, "squares");
  for (int id : ids)
    if (id < 0) throw InputError("damage: ids: must be >= 0, got " + std::to_string(id));
}

void paintSmudges(cv::Mat1f& grey, const VirtualCamera& camera, const std::vector<Eigen::Vector3d>& centres,
                  double radius_mm, float level) {
  for (const Eigen::Vector3d& c : centres) {
    Eigen::Vector2d centre, edge;
    if (!camera.project(camera.camera_from_sensor * c, centre) ||
        !camera.project(camera.camera_from_sensor * (c + Eigen::Vector3d(radius_mm, 0, 0)), edge))
      continue;
    const double radius = (edge - centre).norm();
    forDisc(grey, {centre.x(), centre.y()}, radius, [&](float& g, double d) {
      const double t = std::clamp((radius - d) / (0.4 * radius), 0.0, 1.0);  // 1 in the core, soft rim
      const auto w = static_cast<float>(t * t * (3 - 2 * t));
      g = (1 - w) * g + w * level;
    });
  }
}

}  // namespace onetip::sim
