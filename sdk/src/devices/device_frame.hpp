// devices/device_frame.hpp — the framing of onetip's own small serial
// protocols (the belt device and the wire-driven device):
//
//   frame    := SYNC TYPE LENGTH PAYLOAD[LENGTH] CHECK
//   SYNC     = 0xA5
//   TYPE     : one byte, message type (host -> device < 0x80 <= device -> host)
//   LENGTH   : payload bytes, 0..64
//   CHECK    = (256 - (TYPE + LENGTH + sum(PAYLOAD)) mod 256) mod 256,
//              so TYPE + LENGTH + PAYLOAD + CHECK == 0 (mod 256)
// Multi-byte fields are little-endian, signed ones two's complement.
// The parser resynchronises after a bad length or checksum by dropping the
// sync byte and searching for the next one.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace onetip::devices::frame {

inline constexpr std::uint8_t kSync = 0xA5;
inline constexpr size_t kMaxPayload = 64;

struct Frame {
  std::uint8_t type = 0;
  std::vector<std::uint8_t> payload;
};

std::vector<std::uint8_t> encode(std::uint8_t type, std::span<const std::uint8_t> payload);

class Parser {
 public:
  // Calls on_frame for every complete, valid frame in the bytes so far.
  void feed(std::span<const std::uint8_t> bytes, const std::function<void(const Frame&)>& on_frame);
  std::uint64_t rejected() const noexcept { return rejected_; }

 private:
  std::vector<std::uint8_t> buffer_;
  std::uint64_t rejected_ = 0;
};

// Little-endian field writers and readers.
void putU16(std::vector<std::uint8_t>& out, std::uint16_t v);
void putI16(std::vector<std::uint8_t>& out, std::int16_t v);
void putI32(std::vector<std::uint8_t>& out, std::int32_t v);
std::uint16_t getU16(std::span<const std::uint8_t> in, size_t at);
std::int16_t getI16(std::span<const std::uint8_t> in, size_t at);
std::int32_t getI32(std::span<const std::uint8_t> in, size_t at);

}  // namespace onetip::devices::frame
