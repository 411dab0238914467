#include "os_outputs/axis_scaling.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace onetip::os_outputs {

namespace {
constexpr const char* kAxisNames[kAxisCount] = {"dx", "dy", "dz", "pitch", "roll", "yaw"};

double finiteOrZero(double v) noexcept { return std::isfinite(v) ? v : 0.0; }
}  // namespace

const char* axisName(int axis) noexcept {
  return axis >= 0 && axis < kAxisCount ? kAxisNames[axis] : "?";
}

void WorkingRange::validate() const {
  for (int i = 0; i < kAxisCount; ++i) {
    const AxisInterval& a = axes[static_cast<size_t>(i)];
    const std::string field = std::string("working range ") + kAxisNames[i];
    if (!std::isfinite(a.lo) || !std::isfinite(a.hi)) throw InputError(field + ": bounds must be finite");
    if (!(a.lo < a.hi)) throw InputError(field + ": lo must be less than hi");
    if (a.lo > 0 || a.hi < 0) throw InputError(field + ": must contain 0 (the pose at contact onset)");
  }
}

std::array<double, kAxisCount> toAxisOrder(const Input6& in) noexcept {
  return {finiteOrZero(in.dx),    finiteOrZero(in.dy),   finiteOrZero(in.dz),
          finiteOrZero(in.pitch), finiteOrZero(in.roll), finiteOrZero(in.yaw)};
}

std::array<std::int32_t, kAxisCount> spnavAxes(const Input6& in, const WorkingRange& range,
                                               double full_scale) noexcept {
  const auto v = toAxisOrder(in);
  std::array<std::int32_t, kAxisCount> out{};
  for (size_t i = 0; i < out.size(); ++i) {
    const AxisInterval& a = range.axes[i];
    const double m = std::max(std::abs(a.lo), std::abs(a.hi));
    const double normalised = std::clamp(v[i] / m, -1.0, 1.0);
    out[i] = static_cast<std::int32_t>(std::lround(normalised * full_scale));
  }
  return out;
}

std::array<std::int32_t, kAxisCount> joystickAxes(const Input6& in, const WorkingRange& range) noexcept {
  const auto v = toAxisOrder(in);
  std::array<std::int32_t, kAxisCount> out{};
  for (size_t i = 0; i < out.size(); ++i) {
    const AxisInterval& a = range.axes[i];
    const double unit = 2.0 * (std::clamp(v[i], a.lo, a.hi) - a.lo) / (a.hi - a.lo) - 1.0;
    out[i] = static_cast<std::int32_t>(std::lround(unit * kJoystickAxisMax));
  }
  return out;
}

}  // namespace onetip::os_outputs
