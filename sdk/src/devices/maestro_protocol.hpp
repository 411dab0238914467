// devices/maestro_protocol.hpp — the Pololu Maestro servo controller's
// compact serial protocol (Maestro user's guide, "Serial Servo Commands").
//
// Every command is a command byte (bit 7 set) followed by data bytes (bit 7
// clear); 14-bit values travel as two 7-bit bytes, low bits first:
//   Set Target        0x84, channel, target & 0x7F, (target >> 7) & 0x7F
//                     target in quarter-microseconds (0..16383; 0 = pulses off)
//   Set Speed         0x87, channel, speed low 7, speed high 7
//                     speed in (0.25 us) / (10 ms); 0 = unlimited
//   Set Acceleration  0x89, channel, accel low 7, accel high 7
//                     accel in (0.25 us) / (10 ms) / (80 ms), 0..255; 0 = unlimited
//   Get Position      0x90, channel  -> reply: two bytes, position low 8 bits
//                     then high 8 bits, in quarter-microseconds
// Channels are 0..23 (the largest Maestro).
#pragma once

#include <array>
#include <cstdint>
#include <span>

namespace onetip::devices::maestro {

inline constexpr std::uint8_t kSetTarget = 0x84;
inline constexpr std::uint8_t kSetSpeed = 0x87;
inline constexpr std::uint8_t kSetAcceleration = 0x89;
inline constexpr std::uint8_t kGetPosition = 0x90;
inline constexpr int kMaxChannel = 23;
inline constexpr int kMaxTarget = 16383;  // 14 bits
inline constexpr int kMaxAcceleration = 255;

// A 4-byte command with a 14-bit value (InputError when channel or value is out of range).
std::array<std::uint8_t, 4> encode14(std::uint8_t command, int channel, int value);
inline std::array<std::uint8_t, 4> setTarget(int channel, int quarter_us) { return encode14(kSetTarget, channel, quarter_us); }
inline std::array<std::uint8_t, 4> setSpeed(int channel, int speed) { return encode14(kSetSpeed, channel, speed); }
std::array<std::uint8_t, 4> setAcceleration(int channel, int acceleration);
std::array<std::uint8_t, 2> getPosition(int channel);
// The Get Position reply as quarter-microseconds.
int decodePosition(std::span<const std::uint8_t, 2> reply);

}  // namespace onetip::devices::maestro
