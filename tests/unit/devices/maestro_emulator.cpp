#include "maestro_emulator.hpp"

#include <algorithm>
#include <cmath>

namespace onetip::devices::testing {

MaestroEmulator::MaestroEmulator(int channels) : channels_(channels) { start(); }
MaestroEmulator::~MaestroEmulator() { stop(); }

std::vector<MaestroEvent> MaestroEmulator::events() const {
  std::lock_guard lock(mutex_);
  return events_;
}

std::vector<MaestroEvent> MaestroEmulator::events(std::uint8_t command) const {
  std::vector<MaestroEvent> out;
  for (const auto& e : events())
    if (e.command == command) out.push_back(e);
  return out;
}

void MaestroEmulator::clear() {
  std::lock_guard lock(mutex_);
  events_.clear();
}

void MaestroEmulator::onBytes(std::span<const std::uint8_t> bytes, Clock::time_point t) {
  std::lock_guard lock(mutex_);
  for (std::uint8_t b : bytes) {
    const bool is_command = (b & 0x80) != 0;
    if (pending_.empty()) {
      if (!is_command) {
        violation("data byte " + std::to_string(b) + " where a command byte was expected");
        continue;
      }
      if (b != 0x84 && b != 0x87 && b != 0x89 && b != 0x90) {
        violation("unknown command byte " + std::to_string(b));
        continue;
      }
    } else if (is_command) {
      violation("command byte " + std::to_string(b) + " inside a command's data");
      pending_.clear();
    }
    pending_.push_back(b);
    const size_t length = pending_[0] == 0x90 ? 2 : 4;
    if (pending_.size() == length) complete(t);
  }
}

double MaestroEmulator::positionAt(int channel, Clock::time_point t) {
  Servo& s = servos_[channel];
  const double ticks = std::chrono::duration<double>(t - s.updated).count() / 0.010;
  const double gap = s.target_qus - s.position_qus;
  const double step = s.speed == 0 ? std::abs(gap) : std::min(std::abs(gap), s.speed * ticks);
  s.position_qus += std::copysign(step, gap);
  s.updated = t;
  return s.position_qus;
}

void MaestroEmulator::complete(Clock::time_point t) {
  const std::uint8_t command = pending_[0];
  const int channel = pending_[1];
  int value = -1;
  if (pending_.size() == 4) value = pending_[2] | (pending_[3] << 7);
  pending_.clear();
  if (channel >= channels_) {
    violation("channel " + std::to_string(channel) + " does not exist");
    return;
  }
  events_.push_back({t, command, channel, value});
  positionAt(channel, t);
  Servo& s = servos_[channel];
  if (command == 0x84) s.target_qus = value;
  if (command == 0x87) s.speed = value;
  if (command == 0x89 && value > 255) violation("acceleration " + std::to_string(value) + " above 255");
  if (command == 0x90) {
    const int p = static_cast<int>(std::lround(s.target_qus == 0 ? 0.0 : s.position_qus));
    const std::uint8_t r[2] = {static_cast<std::uint8_t>(p & 0xFF), static_cast<std::uint8_t>(p >> 8)};
    reply(r);
  }
}

}  // namespace onetip::devices::testing
