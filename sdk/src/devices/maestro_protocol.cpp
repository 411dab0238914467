#include "devices/maestro_protocol.hpp"

#include <string>

#include "core/error.hpp"

namespace onetip::devices::maestro {
namespace {
void checkChannel(int channel) {
  if (channel < 0 || channel > kMaxChannel)
    throw InputError("Maestro channel " + std::to_string(channel) + ": must be in [0, 23]");
}
}  // namespace

std::array<std::uint8_t, 4> encode14(std::uint8_t command, int channel, int value) {
  checkChannel(channel);
  if (value < 0 || value > kMaxTarget)
    throw InputError("Maestro value " + std::to_string(value) + ": must be in [0, 16383]");
  return {command, static_cast<std::uint8_t>(channel), static_cast<std::uint8_t>(value & 0x7F),
          static_cast<std::uint8_t>((value >> 7) & 0x7F)};
}

std::array<std::uint8_t, 4> setAcceleration(int channel, int acceleration) {
  if (acceleration < 0 || acceleration > kMaxAcceleration)
    throw InputError("Maestro acceleration " + std::to_string(acceleration) + ": must be in [0, 255]");
  return encode14(kSetAcceleration, channel, acceleration);
}

std::array<std::uint8_t, 2> getPosition(int channel) {
  checkChannel(channel);
  return {kGetPosition, static_cast<std::uint8_t>(channel)};
}

int decodePosition(std::span<const std::uint8_t, 2> reply) { return reply[0] | (reply[1] << 8); }

}  // namespace onetip::devices::maestro
