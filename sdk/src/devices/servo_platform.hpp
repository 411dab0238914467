// devices/servo_platform.hpp — the 3-servo cable platform of the kNN papers
// driven through a Pololu Maestro (maestro_protocol.hpp).
//
// Goal: the three servo angles in degrees (m1 front, m2 rear right, m3 rear
// left; haptics/platform_kinematics.hpp), what the kNN renderer produces.
// Outputs: the same angles, kept in [30, 195] deg, stepping at most
// max_speed_deg_s / rate_hz per command (the servo's limit: 60 deg in 0.07 s,
// 857 deg/s, so 17.1 deg per 20 ms at 50 Hz); rest (retracted) 30 deg.
// On every (re)connection each channel gets Set Speed with the same limit in
// Maestro units, speed = floor(4 * |us_per_deg| * max_speed_deg_s / 100)
// (0.25 us per 10 ms), and Set Acceleration `acceleration`. Each period sends
// three Set Target commands (calibrated pulse widths) and, with
// read_positions, asks Get Position on each channel for status().measured.
#pragma once

#include <array>

#include "devices/serial_device_loop.hpp"
#include "devices/servo_calibration.hpp"

namespace onetip::devices {

struct ServoPlatformOptions {
  SerialOptions serial;                  // the Maestro accepts up to 200000 baud: <= 115200 here
  std::array<int, 3> channels{0, 1, 2};  // Maestro channel of m1, m2, m3
  PlatformServoCalibration calibration{};
  double rate_hz = 50.0;
  double max_speed_deg_s = 60.0 / 0.07;
  int acceleration = 0;                  // Maestro units, 0 = unlimited
  bool read_positions = true;
  double watchdog_timeout_s = 0.1;
  void validate() const;                 // throws InputError naming the bad field
};

SafeLimits servoPlatformLimits(const ServoPlatformOptions& options);
// Set Speed value of one servo for the speed limit.
int maestroSpeedUnits(const ServoCalibration& calibration, double max_speed_deg_s);

class ServoPlatform final : public SerialDeviceLoop {
 public:
  explicit ServoPlatform(ServoPlatformOptions options);
  ~ServoPlatform() override;

 private:
  void validateConfiguration() const override;
  void configureDevice(SerialPort& port) override;
  std::vector<double> outputsFor(std::span<const double> goal, double dt_s) override;
  void sendOutputs(SerialPort& port, std::span<const double> outputs) override;
  std::vector<double> readFeedback(SerialPort& port) override;

  ServoPlatformOptions options_;
};

// `onetip servo`: opens the port, sets the speed limit and acceleration, sends
// one target per servo clamped to [30, 195] deg and returns the angles sent.
// InputError for a bad port, options or a non-finite angle.
std::array<double, 3> sendServoTargetsOnce(const ServoPlatformOptions& options, const std::array<double, 3>& degrees);

}  // namespace onetip::devices
