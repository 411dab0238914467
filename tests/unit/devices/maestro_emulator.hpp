// tests/unit/devices/maestro_emulator.hpp — a Pololu Maestro's compact serial
// protocol, decoded independently of the driver from the user's guide:
// command bytes have bit 7 set, data bytes not; 0x84 / 0x87 / 0x89 take a
// channel and a 14-bit value (low 7 bits first), 0x90 a channel and is
// answered with the position as two bytes, low byte first. The emulated
// servo moves towards its target at the Set Speed limit (0.25 us per 10 ms).
// Anything else is recorded as a violation.
#pragma once

#include <map>

#include "pty_emulator.hpp"

namespace onetip::devices::testing {

struct MaestroEvent {
  Clock::time_point t;
  std::uint8_t command;
  int channel;
  int value;  // target / speed / acceleration; -1 for Get Position
};

class MaestroEmulator final : public PtyEmulator {
 public:
  explicit MaestroEmulator(int channels = 6);
  ~MaestroEmulator() override;
  std::vector<MaestroEvent> events() const;
  std::vector<MaestroEvent> events(std::uint8_t command) const;
  void clear();

 private:
  void onBytes(std::span<const std::uint8_t> bytes, Clock::time_point t) override;
  void complete(Clock::time_point t);
  double positionAt(int channel, Clock::time_point t);

  int channels_;
  std::vector<std::uint8_t> pending_;
  std::vector<MaestroEvent> events_;
  struct Servo {
    double position_qus = 6000.0;
    int target_qus = 0;
    int speed = 0;
    Clock::time_point updated = Clock::now();
  };
  std::map<int, Servo> servos_;
};

}  // namespace onetip::devices::testing
