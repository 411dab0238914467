// tests/unit/devices/wire_plant.hpp — a simulated 3-DoF wire device on a
// fingertip, the plant the force controller is tested against.
//
// Motors: each cable tension follows its command with a first-order lag
// (motor_time_constant_s). Plate: massless, its lateral position and yaw held
// by skin friction; its height hz and tilt (roll about y, pitch about x) are
// where the forces balance, solved by Newton's method each step:
//   z:      sum_i (T_i - k x_i) d_i.z = k_f max(hz, 0)^2        (finger, Eq. 2.5)
//   torque: sum_i (R b_i) x (T_i - k x_i) d_i = k_theta (pitch, roll)  (x, y parts)
// with the device geometry of wire_device_geometry.hpp (the physical truth).
// The force on the finger is sum_i (T_i - k x_i) d_i. Sensors: FSR = k_f hz^2
// plus Gaussian noise; IMU rotation = true rotation times a random small
// rotation (Gaussian angles).
#pragma once

#include <Eigen/Core>
#include <random>

#include "devices/wire_device_geometry.hpp"

namespace onetip::devices::testing {

struct WirePlantOptions {
  double motor_time_constant_s = 0.01;
  double rotational_stiffness_nmm_per_rad = 20.0;  // k_theta of the fingertip
  double fsr_noise_n = 0.01;
  double imu_noise_deg = 0.3;
  unsigned seed = 7;
};

class WirePlant {
 public:
  WirePlant(const WireDeviceGeometry& geometry, const WirePlantOptions& options = {});
  // Advances dt seconds with the commanded tensions (N), in substeps.
  void advance(const Eigen::Vector3d& tension_command, double dt_s, int substeps = 4);
  Eigen::Vector3d contactForce() const;
  double normalForce() const;      // k_f hz^2 (noise-free FSR)
  double rollDeg() const;
  double pitchDeg() const;
  Eigen::Matrix3d trueRotation() const;
  Eigen::Matrix3d measuredRotation();
  double measuredFsr();

 private:
  Eigen::Vector3d residual(const Eigen::Vector3d& q) const;
  void solveEquilibrium();
  WireDeviceGeometry g_;
  WirePlantOptions o_;
  Eigen::Vector3d tension_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d q_ = Eigen::Vector3d::Zero();  // hz (mm), roll, pitch (rad)
  std::mt19937 rng_;
};

}  // namespace onetip::devices::testing
