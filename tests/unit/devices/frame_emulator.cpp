#include "frame_emulator.hpp"

#include <algorithm>
#include <cmath>

namespace onetip::devices::testing {
namespace {
std::int32_t i32(const std::vector<std::uint8_t>& p, size_t at) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(p[at]) | (static_cast<std::uint32_t>(p[at + 1]) << 8) |
                                   (static_cast<std::uint32_t>(p[at + 2]) << 16) |
                                   (static_cast<std::uint32_t>(p[at + 3]) << 24));
}
int u16(const std::vector<std::uint8_t>& p, size_t at) { return p[at] | (p[at + 1] << 8); }
void put16(std::vector<std::uint8_t>& p, int v) {
  p.push_back(static_cast<std::uint8_t>(v & 0xFF));
  p.push_back(static_cast<std::uint8_t>((v >> 8) & 0xFF));
}
}  // namespace

std::vector<FrameEvent> FrameEmulator::events() const {
  std::lock_guard lock(mutex_);
  return events_;
}

std::vector<FrameEvent> FrameEmulator::events(std::uint8_t type) const {
  std::vector<FrameEvent> out;
  for (const auto& e : events())
    if (e.type == type) out.push_back(e);
  return out;
}

void FrameEmulator::clear() {
  std::lock_guard lock(mutex_);
  events_.clear();
}

void FrameEmulator::onBytes(std::span<const std::uint8_t> bytes, Clock::time_point t) {
  std::lock_guard lock(mutex_);
  pending_.insert(pending_.end(), bytes.begin(), bytes.end());
  while (!pending_.empty()) {
    if (pending_[0] != 0xA5) {
      violation("byte " + std::to_string(pending_[0]) + " outside a frame");
      pending_.erase(pending_.begin());
      continue;
    }
    if (pending_.size() < 3) return;
    const size_t length = pending_[2];
    if (length > 64) {
      violation("frame length " + std::to_string(length));
      pending_.erase(pending_.begin());
      continue;
    }
    if (pending_.size() < length + 4) return;
    unsigned sum = 0;
    for (size_t i = 1; i < length + 4; ++i) sum += pending_[i];
    const std::vector<std::uint8_t> payload(pending_.begin() + 3, pending_.begin() + 3 + static_cast<long>(length));
    const std::uint8_t type = pending_[1];
    pending_.erase(pending_.begin(), pending_.begin() + static_cast<long>(length + 4));
    if ((sum & 0xFF) != 0) {
      violation("bad checksum on a frame of type " + std::to_string(type));
      continue;
    }
    std::vector<double> values;
    if (!decode(type, payload, values)) {
      violation("unknown frame type " + std::to_string(type) + " or length " + std::to_string(length));
      continue;
    }
    events_.push_back({t, type, values});
  }
}

void FrameEmulator::send(std::uint8_t type, const std::vector<std::uint8_t>& payload) {
  std::vector<std::uint8_t> f{0xA5, type, static_cast<std::uint8_t>(payload.size())};
  unsigned sum = type + static_cast<unsigned>(payload.size());
  for (std::uint8_t b : payload) {
    f.push_back(b);
    sum += b;
  }
  f.push_back(static_cast<std::uint8_t>((256 - (sum & 0xFF)) & 0xFF));
  reply(f);
}

BeltEmulator::BeltEmulator(double counts_per_rev) : counts_per_rev_(counts_per_rev) { start(); }
BeltEmulator::~BeltEmulator() { stop(); }

double BeltEmulator::feedbackRateHz() const {
  std::lock_guard lock(mutex_);
  return rate_hz_;
}

bool BeltEmulator::decode(std::uint8_t type, const std::vector<std::uint8_t>& p, std::vector<double>& values) {
  if (type == 0x01 && p.size() == 8) {
    values = {i32(p, 0) / 1000.0, i32(p, 4) / 1000.0};
    shaft_deg_ = {values[0], values[1]};
    return true;
  }
  if (type == 0x02 && p.size() == 2) {
    rate_hz_ = u16(p, 0);
    if (rate_hz_ < 1 || rate_hz_ > 1000) violation("feedback rate " + std::to_string(rate_hz_));
    values = {static_cast<double>(rate_hz_)};
    return true;
  }
  return false;
}

void BeltEmulator::onIdle(Clock::time_point now) {
  std::lock_guard lock(mutex_);
  if (rate_hz_ <= 0 || !streaming_ || now < next_feedback_) return;
  next_feedback_ = std::max(next_feedback_ + std::chrono::microseconds(1000000 / rate_hz_), now - std::chrono::milliseconds(5));
  std::vector<std::uint8_t> p;
  put16(p, sequence_++);
  for (double deg : shaft_deg_) {
    const auto counts = static_cast<std::int32_t>(std::lround(deg / 360.0 * counts_per_rev_));
    put16(p, counts & 0xFFFF);
    put16(p, (counts >> 16) & 0xFFFF);
  }
  send(0x81, p);
}

WireEmulator::WireEmulator(double sensor_rate_hz) : rate_hz_(sensor_rate_hz) { start(); }
WireEmulator::~WireEmulator() { stop(); }

bool WireEmulator::decode(std::uint8_t type, const std::vector<std::uint8_t>& p, std::vector<double>& values) {
  if (type != 0x11 || p.size() != 6) return false;
  values = {u16(p, 0) / 1000.0, u16(p, 2) / 1000.0, u16(p, 4) / 1000.0};
  return true;
}

void WireEmulator::onIdle(Clock::time_point now) {
  std::lock_guard lock(mutex_);
  if (!streaming_ || now < next_) return;
  next_ = now + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / rate_hz_));
  // At rest, level, x towards magnetic north: gravity reaction +z (1000 mg),
  // field 20 uT north and 40 uT down (0.01 uT units).
  std::vector<std::uint8_t> p;
  put16(p, sequence_++);
  put16(p, 0);  // FSR: no force
  for (int imu = 0; imu < 2; ++imu)
    for (int v : {0, 0, 1000, 2000, 0, -4000}) put16(p, v);
  send(0x91, p);
}

}  // namespace onetip::devices::testing
