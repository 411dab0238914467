/**
 * @file onetip/joystick_axes.hpp
 * @brief The 6-D input as integer joystick or spacenav axes, scaled exactly
 * like the `onetip joystick` uinput device and the `onetip spnav` server
 * (docs/os_outputs.md), for games that read the sensor in-process.
 *
 * Axis order (both functions and AxisRanges): x = dx, y = dy, z = dz,
 * rx = pitch (about S.x), ry = roll (about S.y), rz = yaw (about S.z); note
 * that this differs from Input6's order. Each axis has an interval [lo, hi]
 * in mm (x, y, z) or degrees (rx, ry, rz); the default is the working range
 * the SDK is built for: dx, dy [-4, 4] mm, dz [0, 3] mm, pitch, roll
 * [-40, 40] deg, yaw [-15, 15] deg.
 *
 *     joystick: value = round((2 * (clamp(v, lo, hi) - lo) / (hi - lo) - 1) * 32767)
 *               (lo -> -32767, hi -> 32767; with the default range the rest pose
 *               gives 0 on every axis but dz, which rests at -32767 like a trigger)
 *     spnav:    units = round(clamp(v / max(|lo|, |hi|), -1, 1) * full_scale)
 *               (the rest pose gives 0; the end of the range +-full_scale)
 *
 * A non-finite component (NaN, infinity) is taken as 0, the pose at contact
 * onset. Both functions are pure: any thread, concurrently.
 */
#pragma once

#include <array>
#include <cstdint>

#include "onetip/export.hpp"
#include "onetip/types.hpp"

namespace onetip {

/// The interval of one axis, mm or degrees. Valid when both bounds are finite, lo < hi and lo <= 0 <= hi.
struct AxisInterval {
  double lo = -1, hi = 1;
  /// @var lo
  /// @brief Lower bound, mm or degrees: the input that maps to the joystick's -32767.
  /// @var hi
  /// @brief Upper bound, mm or degrees: the input that maps to the joystick's +32767.
};
/// One interval per axis in axis order x (dx), y (dy), z (dz), rx (pitch), ry (roll), rz (yaw); mm for x..z, degrees for rx..rz.
using AxisRanges = std::array<AxisInterval, 6>;

/**
 * @brief The default ranges: dx, dy [-4, 4] mm, dz [0, 3] mm, pitch, roll [-40, 40] deg, yaw [-15, 15] deg.
 * @return the ranges in axis order (x, y, z, rx, ry, rz). Any thread; never throws.
 */
ONETIP_EXPORT AxisRanges defaultAxisRanges() noexcept;

/**
 * @brief The 6-D input as absolute joystick axes (what `onetip joystick` reports as ABS_X..ABS_RZ).
 * @param input the 6-D input (Event::input or FrameResult::input), mm and degrees.
 * @param range each axis's interval in axis order (mm, degrees); values outside it are clamped to it.
 * @return the six axes in order x, y, z, rx, ry, rz, each in [-32767, 32767].
 * @throws onetip::Error of kind ErrorKind::input naming the axis when an
 *         interval has a non-finite bound, lo >= hi, or does not contain 0.
 */
ONETIP_EXPORT std::array<std::int32_t, 6> joystickAxes(const Input6& input, const AxisRanges& range = defaultAxisRanges());
/**
 * @brief The 6-D input as spacenav (3Dconnexion) axes (what `onetip spnav` serves).
 * @param input the 6-D input (Event::input or FrameResult::input), mm and degrees.
 * @param range each axis's interval in axis order (mm, degrees); an axis is
 *        normalised by max(|lo|, |hi|) and clamped to [-1, 1].
 * @param full_scale the value of a full deflection, in (0, 1e6]; the default
 *        350 is of the order of a SpaceNavigator's raw counts.
 * @return the six axes in order x, y, z, rx, ry, rz, each in [-full_scale, full_scale] (rounded).
 * @throws onetip::Error of kind ErrorKind::input naming the axis when an
 *         interval has a non-finite bound, lo >= hi, or does not contain 0,
 *         or when full_scale is not in (0, 1e6] (NaN included).
 */
ONETIP_EXPORT std::array<std::int32_t, 6> spnavAxes(const Input6& input, const AxisRanges& range = defaultAxisRanges(),
                                                     double full_scale = 350);

}  // namespace onetip
