#include "contact/lattice_hole.hpp"

#include <utility>

namespace onetip::contact {

bool latticeInterpolant(int rows, int cols, int id, const std::vector<Eigen::Vector3d>& position,
                        const std::vector<Eigen::Vector3d>& displacement, const std::vector<std::uint8_t>& measured,
                        LatticeSample& out) {
  const int r = id / cols, c = id % cols;
  auto measuredAt = [&](int rr, int cc) {
    return rr >= 0 && rr < rows && cc >= 0 && cc < cols && measured[static_cast<size_t>(rr * cols + cc)];
  };
  out = LatticeSample{};
  int pairs = 0;
  for (const auto& step : {std::pair{0, 1}, std::pair{1, 0}}) {
    const int dr = step.first, dc = step.second;  // a lambda may not capture a structured binding before clang 16
    if (!measuredAt(r - dr, c - dc) || !measuredAt(r + dr, c + dc)) continue;
    auto at = [&](int k) { return static_cast<size_t>((r + k * dr) * cols + c + k * dc); };
    // Cubic through the four neighbours -2, -1, +1, +2 where all are measured: weights (-1, 4, 4, -1) / 6.
    const bool cubic = measuredAt(r - 2 * dr, c - 2 * dc) && measuredAt(r + 2 * dr, c + 2 * dc);
    const double near = cubic ? 4.0 / 6 : 0.5, far = cubic ? -1.0 / 6 : 0.0;
    out.position += near * (position[at(-1)] + position[at(1)]);
    out.displacement += near * (displacement[at(-1)] + displacement[at(1)]);
    if (cubic) {
      out.position += far * (position[at(-2)] + position[at(2)]);
      out.displacement += far * (displacement[at(-2)] + displacement[at(2)]);
    }
    ++pairs;
  }
  if (pairs == 0) return false;
  out.position /= pairs;
  out.displacement /= pairs;
  return true;
}

}  // namespace onetip::contact
