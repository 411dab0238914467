// tests/unit/devices/frame_emulator.hpp — firmware emulators for onetip's own
// framed protocols (devices/device_frame.hpp), decoding the bytes
// independently of the driver: SYNC 0xA5, TYPE, LENGTH <= 64, PAYLOAD, CHECK
// with TYPE + LENGTH + PAYLOAD + CHECK == 0 mod 256. A byte that does not
// start a frame, a bad checksum or an unknown type is a violation.
//   BeltEmulator: SET_ANGLES (0x01, 2 x int32 millidegrees) and
//     SET_FEEDBACK_RATE (0x02, uint16 Hz); streams ENCODER (0x81) frames at
//     the set rate with the shafts at the last target.
//   WireEmulator: SET_PWM (0x11, 3 x uint16 per mille); streams SENSORS
//     (0x91) at sensor_rate_hz for a device at rest, level, facing north.
#pragma once

#include <array>

#include "pty_emulator.hpp"

namespace onetip::devices::testing {

struct FrameEvent {
  Clock::time_point t;
  std::uint8_t type;
  std::vector<double> values;  // decoded fields (degrees, Hz or duty)
};

class FrameEmulator : public PtyEmulator {
 public:
  std::vector<FrameEvent> events() const;
  std::vector<FrameEvent> events(std::uint8_t type) const;
  void clear();
  void setStreaming(bool on) { streaming_ = on; }

 protected:
  // Decodes one frame's payload; returns false for an unknown type or length.
  virtual bool decode(std::uint8_t type, const std::vector<std::uint8_t>& payload, std::vector<double>& values) = 0;
  void send(std::uint8_t type, const std::vector<std::uint8_t>& payload);
  std::vector<FrameEvent> events_;
  std::atomic<bool> streaming_{true};

 private:
  void onBytes(std::span<const std::uint8_t> bytes, Clock::time_point t) override;
  std::vector<std::uint8_t> pending_;
};

class BeltEmulator final : public FrameEmulator {
 public:
  explicit BeltEmulator(double counts_per_rev = 65536.0);
  ~BeltEmulator() override;
  double feedbackRateHz() const;

 private:
  bool decode(std::uint8_t type, const std::vector<std::uint8_t>& payload, std::vector<double>& values) override;
  void onIdle(Clock::time_point now) override;
  double counts_per_rev_;
  int rate_hz_ = 0;
  std::array<double, 2> shaft_deg_{0.0, 0.0};
  Clock::time_point next_feedback_{};
  std::uint16_t sequence_ = 0;
};

class WireEmulator final : public FrameEmulator {
 public:
  explicit WireEmulator(double sensor_rate_hz = 200.0);
  ~WireEmulator() override;

 private:
  bool decode(std::uint8_t type, const std::vector<std::uint8_t>& payload, std::vector<double>& values) override;
  void onIdle(Clock::time_point now) override;
  double rate_hz_;
  Clock::time_point next_{};
  std::uint16_t sequence_ = 0;
};

}  // namespace onetip::devices::testing
