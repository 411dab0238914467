#include "devices/device_frame.hpp"

#include <algorithm>
#include <cassert>

namespace onetip::devices::frame {
namespace {
std::uint8_t checkOf(std::uint8_t type, std::span<const std::uint8_t> payload) {
  unsigned sum = type + static_cast<unsigned>(payload.size());
  for (std::uint8_t b : payload) sum += b;
  return static_cast<std::uint8_t>((256u - (sum & 0xFFu)) & 0xFFu);
}
}  // namespace

std::vector<std::uint8_t> encode(std::uint8_t type, std::span<const std::uint8_t> payload) {
  assert(payload.size() <= kMaxPayload);
  std::vector<std::uint8_t> out(payload.size() + 4);
  out[0] = kSync;
  out[1] = type;
  out[2] = static_cast<std::uint8_t>(payload.size());
  std::copy(payload.begin(), payload.end(), out.begin() + 3);
  out.pop_back();
  out.push_back(checkOf(type, payload));
  return out;
}

void Parser::feed(std::span<const std::uint8_t> bytes, const std::function<void(const Frame&)>& on_frame) {
  buffer_.insert(buffer_.end(), bytes.begin(), bytes.end());
  size_t at = 0;
  while (true) {
    while (at < buffer_.size() && buffer_[at] != kSync) ++at;
    if (buffer_.size() - at < 3) break;
    const size_t length = buffer_[at + 2];
    if (length > kMaxPayload) {
      ++rejected_;
      ++at;
      continue;
    }
    if (buffer_.size() - at < 4 + length) break;
    const std::span<const std::uint8_t> payload(buffer_.data() + at + 3, length);
    if (checkOf(buffer_[at + 1], payload) != buffer_[at + 3 + length]) {
      ++rejected_;
      ++at;
      continue;
    }
    on_frame(Frame{buffer_[at + 1], {payload.begin(), payload.end()}});
    at += 4 + length;
  }
  buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<long>(at));
}

void putU16(std::vector<std::uint8_t>& out, std::uint16_t v) {
  out.push_back(static_cast<std::uint8_t>(v & 0xFF));
  out.push_back(static_cast<std::uint8_t>(v >> 8));
}
void putI16(std::vector<std::uint8_t>& out, std::int16_t v) { putU16(out, static_cast<std::uint16_t>(v)); }
void putI32(std::vector<std::uint8_t>& out, std::int32_t v) {
  const auto u = static_cast<std::uint32_t>(v);
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>((u >> (8 * i)) & 0xFF));
}
std::uint16_t getU16(std::span<const std::uint8_t> in, size_t at) {
  return static_cast<std::uint16_t>(in[at] | (in[at + 1] << 8));
}
std::int16_t getI16(std::span<const std::uint8_t> in, size_t at) { return static_cast<std::int16_t>(getU16(in, at)); }
std::int32_t getI32(std::span<const std::uint8_t> in, size_t at) {
  std::uint32_t u = 0;
  for (int i = 0; i < 4; ++i) u |= static_cast<std::uint32_t>(in[at + i]) << (8 * i);
  return static_cast<std::int32_t>(u);
}

}  // namespace onetip::devices::frame
