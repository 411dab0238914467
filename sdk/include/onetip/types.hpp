/**
 * @file onetip/types.hpp
 * @brief The plain value types shared by every part of the SDK: the contact
 * state, the 6-D input vector and a marker position.
 *
 * Frames and units (docs/reference.md): positions in millimetres in the
 * sensor frame S, user-facing angles in degrees. S is derived from the rest
 * state (no contact) of the marker grid: origin at the centroid of the
 * rest-state 3-D marker positions; z the normal of the least-squares plane
 * through them, pointing out of the pad towards the finger (away from the
 * camera); x the direction of increasing marker column, projected onto that
 * plane; y = z × x (right-handed). By default the finger's long axis lies
 * along y.
 *
 * These are plain values: no ownership, no shared state; any thread may use
 * its own copies.
 */
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

namespace onetip {

/// The contact state of a frame (the `state` column of pose.csv).
enum class ContactState : std::uint8_t {
  none = 0,          ///< No contact.
  stick = 1,         ///< In contact; no contact marker slips (the pad moves with the finger).
  partial_slip = 2,  ///< In contact; some contact markers slip while others stick.
  slip = 3           ///< In contact; the whole contact slips (no marker sticks).
};

/**
 * @brief The name used in CSV files and logs.
 * @param s a contact state; a value outside the enumerators gives "none".
 * @return "none", "stick", "partial_slip" or "slip" (a static string).
 */
constexpr std::string_view toString(ContactState s) noexcept {
  switch (s) {
    case ContactState::stick: return "stick";
    case ContactState::partial_slip: return "partial_slip";
    case ContactState::slip: return "slip";
    case ContactState::none: break;
  }
  return "none";
}

/**
 * @brief The 6-D input vector [dx, dy, dz, yaw, pitch, roll]: the finger's
 * motion since contact onset (docs/reference.md).
 *
 * Let T = T_now * inverse(T_onset) be the finger's rigid motion in the sensor
 * frame S since the contact began, and c0 the centroid of the contact region
 * at onset. Then dx, dy are the S.x and S.y components of T(c0) - c0 (mm); dz
 * is the press depth -(T(c0) - c0).z (mm, positive into the pad); yaw, pitch,
 * roll are degrees with R = Rz(yaw) * Ry(roll) * Rx(pitch) the rotation of T:
 * yaw about S.z (twist on the spot), pitch about S.x (tip up/down), roll about
 * S.y (the finger's long axis), signs by the right-hand rule. All zero out of
 * contact. The working range the SDK is built for: dx, dy in [-4, 4] mm, dz in
 * [0, 3] mm, yaw in [-15, 15] deg, pitch and roll in [-40, 40] deg
 * (SensorOptions::working_range).
 */
struct Input6 {
  double dx = 0, dy = 0, dz = 0;
  /// @var dx
  /// @brief Slide along S.x, mm.
  /// @var dy
  /// @brief Slide along S.y, mm.
  /// @var dz
  /// @brief Press depth, mm, positive into the pad.
  double yaw = 0, pitch = 0, roll = 0;
  /// @var yaw
  /// @brief Twist on the spot, about S.z, degrees.
  /// @var pitch
  /// @brief Tip up/down, about S.x, degrees.
  /// @var roll
  /// @brief About S.y (the finger's long axis), degrees.

  /// @return {dx, dy, dz, yaw, pitch, roll}, in that order (mm, mm, mm, deg, deg, deg).
  std::array<double, 6> asArray() const noexcept { return {dx, dy, dz, yaw, pitch, roll}; }
  /**
   * @brief The inverse of asArray().
   * @param a {dx, dy, dz, yaw, pitch, roll} in mm and degrees; copied as is (no check).
   * @return the vector with those components.
   */
  static Input6 fromArray(const std::array<double, 6>& a) noexcept {
    return {a[0], a[1], a[2], a[3], a[4], a[5]};
  }
};

/// A marker position in the sensor frame S, millimetres.
struct MarkerPoint {
  int id = 0;  ///< Marker id = row * cols + col of the pattern grid.
  double x = 0, y = 0, z = 0;
  /// @var x
  /// @brief Position along S.x, mm.
  /// @var y
  /// @brief Position along S.y, mm.
  /// @var z
  /// @brief Position along S.z (out of the pad), mm.
};

}  // namespace onetip
