// os_outputs/axis_scaling.hpp — the 6-D input [dx, dy, dz, yaw, pitch, roll]
// (mm, mm, mm, deg, deg, deg; docs/reference.md) as integer axes for other programs.
//
// Axis order, shared by both outputs (the rotation axes are the axes the
// rotation turns about, in the sensor frame S):
//   0 x  = dx      (mm along S.x)            spnav x,  uinput ABS_X
//   1 y  = dy      (mm along S.y)            spnav y,  uinput ABS_Y
//   2 z  = dz      (press depth, mm)         spnav z,  uinput ABS_Z
//   3 rx = pitch   (deg about S.x)           spnav rx, uinput ABS_RX
//   4 ry = roll    (deg about S.y)           spnav ry, uinput ABS_RY
//   5 rz = yaw     (deg about S.z)           spnav rz, uinput ABS_RZ
//
// WorkingRange gives each axis its interval [lo, hi] in mm or degrees; the
// default is the paper's working range: dx, dy in [-4, 4] mm, dz in [0, 3] mm,
// yaw in [-15, 15] deg, pitch and roll in [-40, 40] deg.
//
// spnav (a rate device that rests at 0): with m = max(|lo|, |hi|),
//   units = round(clamp(v / m, -1, 1) * full_scale)
// so the rest pose is 0 and the end of the range is ±full_scale (default 350,
// the order of a 3Dconnexion SpaceNavigator's raw counts). Example: dx = 2 mm
// with the default range gives round(2 / 4 * 350) = 175.
//
// uinput joystick (an absolute axis over the whole range):
//   value = round((2 * (clamp(v, lo, hi) - lo) / (hi - lo) - 1) * 32767)
// so lo -> -32767, hi -> +32767 (Sint16-friendly, symmetric); with the default
// range the rest pose gives 0 on every axis but dz, which rests at -32767 like
// a trigger. Example: dz = 1.5 mm -> 0, pitch = 20 deg -> round(0.5 * 32767) = 16384.
//
// Non-finite inputs map to the rest value of that axis (0 mm / 0 deg).
#pragma once

#include <array>
#include <cstdint>

#include "onetip/types.hpp"

namespace onetip::os_outputs {

inline constexpr int kAxisCount = 6;
inline constexpr std::int32_t kJoystickAxisMax = 32767;

struct AxisInterval {
  double lo = -1, hi = 1;
};

struct WorkingRange {
  // In axis order x, y, z, rx, ry, rz (see above): mm for x..z, degrees for rx..rz.
  std::array<AxisInterval, kAxisCount> axes{{{-4, 4}, {-4, 4}, {0, 3}, {-40, 40}, {-40, 40}, {-15, 15}}};
  // Throws InputError naming the axis when an interval is not finite, lo >= hi,
  // or (for spnav) does not contain 0.
  void validate() const;
};

// Names of the axes in axis order: "dx", "dy", "dz", "pitch", "roll", "yaw".
const char* axisName(int axis) noexcept;

// The 6-D input in axis order (dx, dy, dz, pitch, roll, yaw).
std::array<double, kAxisCount> toAxisOrder(const Input6& in) noexcept;

// spnav units in axis order; full_scale > 0 (may be fractional when a client's
// sensitivity multiplies it).
std::array<std::int32_t, kAxisCount> spnavAxes(const Input6& in, const WorkingRange& range,
                                               double full_scale) noexcept;

// uinput absolute values in ABS_X..ABS_RZ order, each in [-32767, 32767].
std::array<std::int32_t, kAxisCount> joystickAxes(const Input6& in, const WorkingRange& range) noexcept;

}  // namespace onetip::os_outputs
