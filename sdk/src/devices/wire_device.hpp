// devices/wire_device.hpp — the 3-DoF wire-driven device (thesis Sec. 2.2):
// three micro DC motors pull cables to a contact plate with an FSR and an IMU;
// a second IMU sits on the body. The controller (wire_force_controller.hpp)
// runs in the driver at rate_hz on the latest sensor frame.
//
// Goal: the desired contact force fd = [fx, fy, fz] (N, body frame of
// wire_device_geometry.hpp, fz pressing into the pad). It is first limited to
// what the device can display: fz in [0, max_force_n], |(fx, fy)| <= fz
// tan(max_tilt_deg), |fd| <= max_force_n (scaled down).
// Outputs: PWM duty of the three motors in [0, 1] (u / tension_at_full_pwm_n),
// rest 0, slewing at most max_pwm_rate per second.
// Sensor stall: no sensor frame for sensor_timeout_s -> rest, controller reset.
//
// Wire protocol (frames of device_frame.hpp):
//   0x11 SET_PWM   host -> device  uint16 duty1, duty2, duty3   (1/1000 of full)
//   0x91 SENSORS   device -> host  uint16 sequence, uint16 fsr  (mN),
//                  int16 body accel xyz (mg), body mag xyz (0.01 uT),
//                  int16 plate accel xyz (mg), plate mag xyz (0.01 uT)
// The magnetometer offsets of Eq. 2.12 (imu_orientation.hpp) are subtracted
// before the plate rotation R = R_body^T R_plate is computed.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "devices/device_frame.hpp"
#include "devices/serial_device_loop.hpp"
#include "devices/wire_force_controller.hpp"

namespace onetip::devices::wire {
inline constexpr std::uint8_t kSetPwm = 0x11;
inline constexpr std::uint8_t kSensors = 0x91;
}  // namespace onetip::devices::wire

namespace onetip::devices {

struct WireDeviceOptions {
  SerialOptions serial;
  WireDeviceGeometry geometry;
  WireControllerOptions controller;
  double tension_at_full_pwm_n = 3.0;
  Eigen::Vector3d body_mag_offset_ut = Eigen::Vector3d::Zero();   // Eq. 2.12
  Eigen::Vector3d plate_mag_offset_ut = Eigen::Vector3d::Zero();
  double max_force_n = 1.0;
  double max_tilt_deg = 20.0;
  double rate_hz = 200.0;
  double max_pwm_rate = 50.0;       // full scale per second
  double sensor_timeout_s = 0.05;
  double watchdog_timeout_s = 0.1;
  void validate() const;            // throws InputError naming the bad field
};

// The displayable part of a desired force (see above).
Eigen::Vector3d limitWireForce(const Eigen::Vector3d& fd, double max_force_n, double max_tilt_deg);

class WireDevice final : public SerialDeviceLoop {
 public:
  explicit WireDevice(WireDeviceOptions options);
  ~WireDevice() override;

 private:
  struct Sensors {
    double fsr_n = 0.0;
    Eigen::Matrix3d plate_rotation = Eigen::Matrix3d::Identity();
    std::chrono::steady_clock::time_point received;
  };
  void validateConfiguration() const override;
  void configureDevice(SerialPort& port) override;
  std::vector<double> outputsFor(std::span<const double> goal, double dt_s) override;
  void sendOutputs(SerialPort& port, std::span<const double> outputs) override;
  std::vector<double> readFeedback(SerialPort& port) override;
  void onRetract() override { controller_.reset(); }

  WireDeviceOptions options_;
  WireForceController controller_;
  frame::Parser parser_;
  std::optional<Sensors> sensors_;
};

}  // namespace onetip::devices
