// haptics/command_ramp.hpp — what the 1 kHz display loop sends the servos
// between two rendered commands (render_worker.hpp): a linear ramp from where
// it is to the newest target over `ticks` loop periods, then hold.
//   m(t) = m_0 + (m_target - m_0) * min(1, k / ticks),  k = ticks since the target arrived
// With ticks = the sensor period in loop ticks (10 at 100 Hz / 1 kHz) the
// servos move smoothly instead of stepping every 10 ms; a target arriving
// mid-ramp starts a new ramp from the current position. Degrees.
#pragma once

#include <array>

namespace onetip::haptics {

class CommandRamp {
 public:
  explicit CommandRamp(const std::array<double, 3>& start, int ticks = 10)
      : from_(start), to_(start), now_(start), ticks_(ticks < 1 ? 1 : ticks) {}
  void target(const std::array<double, 3>& m) {
    from_ = now_;
    to_ = m;
    k_ = 0;
  }
  // The command for this tick.
  const std::array<double, 3>& step() {
    if (k_ < ticks_) ++k_;
    const double w = static_cast<double>(k_) / ticks_;
    for (size_t i = 0; i < 3; ++i) now_[i] = from_[i] + (to_[i] - from_[i]) * w;
    return now_;
  }

 private:
  std::array<double, 3> from_, to_, now_;
  int ticks_;
  int k_ = 0;
};

}  // namespace onetip::haptics
