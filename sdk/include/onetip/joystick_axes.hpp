// onetip/joystick_axes.hpp — the 6-D input as joystick axes, scaled exactly
// like the `onetip joystick` uinput device and the `onetip spnav` server
// (docs/os_outputs.md), for games that read the sensor in-process.
//
// Axis order (both functions): x = dx, y = dy, z = dz, rx = pitch (about S.x),
// ry = roll (about S.y), rz = yaw (about S.z). `range` gives each axis's
// [lo, hi] in that order (mm, degrees); the default is the paper's working
// range: dx, dy [-4, 4] mm, dz [0, 3] mm, pitch, roll [-40, 40] deg, yaw [-15, 15] deg.
//   joystick: value = round((2 * (clamp(v, lo, hi) - lo) / (hi - lo) - 1) * 32767)
//             (lo -> -32767, hi -> 32767; at rest dz gives -32767, like a trigger)
//   spnav:    units = round(clamp(v / max(|lo|, |hi|), -1, 1) * full_scale)
// Non-finite values map to the axis's rest value. Throws Error(input) naming
// the axis when an interval is not finite, lo >= hi, or it does not contain 0
// (the pose at contact onset).
#pragma once

#include <array>
#include <cstdint>

#include "onetip/export.hpp"
#include "onetip/types.hpp"

namespace onetip {

struct AxisInterval {
  double lo = -1, hi = 1;
};
using AxisRanges = std::array<AxisInterval, 6>;  // x, y, z, rx, ry, rz

ONETIP_EXPORT AxisRanges defaultAxisRanges() noexcept;
ONETIP_EXPORT std::array<std::int32_t, 6> joystickAxes(const Input6& input, const AxisRanges& range = defaultAxisRanges());
ONETIP_EXPORT std::array<std::int32_t, 6> spnavAxes(const Input6& input, const AxisRanges& range = defaultAxisRanges(),
                                                     double full_scale = 350);

}  // namespace onetip
