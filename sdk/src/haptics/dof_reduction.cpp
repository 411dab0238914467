#include "haptics/dof_reduction.hpp"

#include <cmath>

#include "core/error.hpp"

namespace onetip::haptics {

DeviceDof deviceDofFromInt(int dof) {
  if (dof < 1 || dof > 3) throw InputError("dof: " + std::to_string(dof) + " is not 1, 2 or 3");
  return static_cast<DeviceDof>(dof);
}

void GridSubset::validate() const {
  if (!(step_deg > 0.0) || !std::isfinite(step_deg)) throw InputError("GridSubset.step_deg: must be positive");
  if (!std::isfinite(origin_deg)) throw InputError("GridSubset.origin_deg: must be finite");
  deviceDofFromInt(static_cast<int>(dof));
}

namespace {
bool onGrid(double angle, double origin, double step) {
  const double k = (angle - origin) / step;
  return std::abs(k - std::round(k)) * step <= 1e-3;
}
}  // namespace

bool inSubset(const std::array<double, 3>& m, const GridSubset& s) {
  for (double a : m)
    if (!onGrid(a, s.origin_deg, s.step_deg)) return false;
  constexpr double kSame = 1e-3;
  switch (s.dof) {
    case DeviceDof::one: return std::abs(m[0] - m[1]) <= kSame && std::abs(m[1] - m[2]) <= kSame;
    case DeviceDof::two: return std::abs(m[1] - m[2]) <= kSame;
    case DeviceDof::three: break;
  }
  return true;
}

TactileDataset reduceDataset(const TactileDataset& full, const GridSubset& subset) {
  subset.validate();
  TactileDataset out;
  out.channels = full.channels;
  const auto n = static_cast<size_t>(full.channels);
  for (size_t r = 0; r < full.size(); ++r) {
    const float* m = full.command(r);
    if (!inSubset({m[0], m[1], m[2]}, subset)) continue;
    out.commands.insert(out.commands.end(), m, m + 3);
    out.sensed.insert(out.sensed.end(), full.sensedRow(r), full.sensedRow(r) + n);
  }
  if (out.size() == 0)
    throw InputError("no dataset row lies on the " + std::to_string(subset.step_deg) + "-deg grid with " +
                     std::to_string(static_cast<int>(subset.dof)) + "-DoF");
  return out;
}

}  // namespace onetip::haptics
