// onetip/types.hpp — the plain value types shared by every part of the SDK.
//
// Frames and units follow docs/reference.md: positions in millimetres in the
// sensor frame S (origin at the rest-state marker centroid, z out of the pad
// towards the finger, x along increasing column index, y = z × x); user-facing
// angles in degrees.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

namespace onetip {

// The contact state of a frame (pose.csv column `state`).
enum class ContactState : std::uint8_t { none = 0, stick = 1, partial_slip = 2, slip = 3 };

// Name used in CSV files and logs: "none", "stick", "partial_slip", "slip".
constexpr std::string_view toString(ContactState s) noexcept {
  switch (s) {
    case ContactState::stick: return "stick";
    case ContactState::partial_slip: return "partial_slip";
    case ContactState::slip: return "slip";
    case ContactState::none: break;
  }
  return "none";
}

// The 6-D input vector [dx, dy, dz, yaw, pitch, roll] (docs/reference.md):
// the finger's motion since contact onset, T = T_now * inverse(T_onset).
// dx, dy: mm along S.x, S.y of T(c0) - c0 (c0: contact centroid at onset);
// dz: mm, press depth, -(T(c0) - c0).z, positive into the pad;
// yaw, pitch, roll: degrees, R = Rz(yaw) * Ry(roll) * Rx(pitch).
struct Input6 {
  double dx = 0, dy = 0, dz = 0;
  double yaw = 0, pitch = 0, roll = 0;

  std::array<double, 6> asArray() const noexcept { return {dx, dy, dz, yaw, pitch, roll}; }
  static Input6 fromArray(const std::array<double, 6>& a) noexcept {
    return {a[0], a[1], a[2], a[3], a[4], a[5]};
  }
};

// A marker position in S, millimetres. id = row * cols + col.
struct MarkerPoint {
  int id = 0;
  double x = 0, y = 0, z = 0;
};

}  // namespace onetip
