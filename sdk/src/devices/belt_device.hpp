// devices/belt_device.hpp — the 2-DoF dual-motor belt device (thesis Sec. 2.1):
// two geared DC motors with encoders wind a belt over the fingertip. Rotating
// them in opposite directions (m1 +, m2 -) tightens the belt: normal force;
// in the same direction it slides the belt: shear force (+ along the belt's
// +x when both turn +).
//
// Goal: [normal_N, shear_N]. With F = max_force_n (the 100 % point of the
// user's angle-force table, belt_force_table.hpp):
//   theta_n = table.angleFor(clamp(normal / F, 0, 1))
//   theta_s = sign(shear) * table.angleFor(min(|shear| / F, 1)), then
//             |theta_s| <= theta_max - theta_n (the normal force has priority)
//   m1 = theta_n + theta_s,   m2 = -theta_n + theta_s           (degrees)
// Outputs: m1, m2 in [-theta_max, theta_max] deg, rest 0 (belt slack),
// stepping at most max_speed_deg_s / rate_hz (default 1 kHz control rate).
//
// Wire protocol (frames of device_frame.hpp):
//   0x01 SET_ANGLES          host -> device  int32 m1, int32 m2   (millidegrees)
//   0x02 SET_FEEDBACK_RATE   host -> device  uint16 rate          (Hz, 1..1000)
//   0x81 ENCODER             device -> host  uint16 sequence, int32 c1, int32 c2
//        (encoder counts of the belt shafts, counts_per_rev per revolution)
// The driver sends SET_FEEDBACK_RATE at every (re)connection, SET_ANGLES every
// period, and reports the latest ENCODER angles as status().measured.
#pragma once

#include "devices/belt_force_table.hpp"
#include "devices/device_frame.hpp"
#include "devices/serial_device_loop.hpp"

namespace onetip::devices::belt {
inline constexpr std::uint8_t kSetAngles = 0x01;
inline constexpr std::uint8_t kSetFeedbackRate = 0x02;
inline constexpr std::uint8_t kEncoder = 0x81;
}  // namespace onetip::devices::belt

namespace onetip::devices {

struct BeltDeviceOptions {
  SerialOptions serial;
  std::string force_table_csv;              // the user's table; when empty, force_points
  std::vector<AngleForcePoint> force_points;
  double max_force_n = 1.0;                 // the force at 100 %
  double rate_hz = 1000.0;
  int feedback_rate_hz = 1000;
  double max_speed_deg_s = 720.0;
  double counts_per_rev = 1024.0 * 4.0 * 16.0;  // 1024-line encoder, x4 decoding, 16:1 gear
  double watchdog_timeout_s = 0.1;
  void validate() const;                    // throws InputError naming the bad field
  BeltForceTable loadTable() const;         // InputError for a missing or malformed table
};

class BeltDevice final : public SerialDeviceLoop {
 public:
  // Reads the force table: a missing or malformed one throws InputError here,
  // before the device can be opened; open() checks the remaining options.
  explicit BeltDevice(BeltDeviceOptions options);
  ~BeltDevice() override;
  // The motor angles (deg) for a goal, before the gate (for tests and tools).
  static std::array<double, 2> motorAngles(const BeltForceTable& table, double max_force_n, double normal_n,
                                           double shear_n);

 private:
  void validateConfiguration() const override;
  void configureDevice(SerialPort& port) override;
  std::vector<double> outputsFor(std::span<const double> goal, double dt_s) override;
  void sendOutputs(SerialPort& port, std::span<const double> outputs) override;
  std::vector<double> readFeedback(SerialPort& port) override;

  BeltDeviceOptions options_;
  BeltForceTable table_;
  frame::Parser parser_;
};

}  // namespace onetip::devices
