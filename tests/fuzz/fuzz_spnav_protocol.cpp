// Fuzzes the spacenavd protocol session (os_outputs/spnav_protocol.hpp) as a
// client would drive it: the input is split into reads of 1..64 bytes (sizes
// from the input itself) fed in turn. The session must never grow its state
// without bound, must give whole 4-byte words or 32-byte messages as replies,
// and after garbage it is dropped (no further feeding, as the server does).
#include <cmath>
#include <span>

#include "os_outputs/spnav_protocol.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace onetip::os_outputs::spnav;
  if (size == 0) return 0;
  Session session(DeviceInfo{"fuzz device", "/dev/fuzz", 6, 1});
  std::size_t at = 1;
  std::uint8_t step = data[0];
  while (at < size) {
    const std::size_t n = std::min<std::size_t>(1 + step % 64, size - at);
    const auto r = session.feed(std::span<const std::byte>(reinterpret_cast<const std::byte*>(data + at), n));
    if (r.garbage) break;
    if (r.reply.size() % 4 != 0) __builtin_trap();
    if (!std::isfinite(session.sensitivity())) __builtin_trap();
    at += n;
    step = static_cast<std::uint8_t>(step * 31 + 7);
  }
  return 0;
}
