// devices/imu_orientation.hpp — the wire device's plate rotation from its two
// IMUs, and the magnetometer distortion offset calibration (thesis Eq. 2.12).
//
// Orientation of one IMU at rest (TRIAD): up = a / |a| (the accelerometer
// measures the reaction to gravity), north = the magnetometer reading with its
// vertical part removed, normalised; west = up x north. The rotation from the
// sensor frame to the world (x magnetic north, y west, z up) has the rows
// north, west, up. The plate rotation relative to the body is
//   R = R_body^T R_plate.
// The motors add a constant field Dm to a magnetometer fixed near them; with
// readings with the motors detached (m_undist) and attached (m_dist) in the
// same postures,
//   Dm = sum_i (m_dist,i - m_undist,i) / N                         (Eq. 2.12)
// and a reading is corrected as m - Dm. Units: any (the same for all readings).
#pragma once

#include <Eigen/Core>

namespace onetip::devices {

// World-from-sensor rotation; InputError when a is zero or m is parallel to a.
Eigen::Matrix3d orientationFromAccelMag(const Eigen::Vector3d& accel, const Eigen::Vector3d& mag);

class MagnetometerOffsetCalibration {
 public:
  void add(const Eigen::Vector3d& distorted, const Eigen::Vector3d& undistorted);
  size_t samples() const noexcept { return n_; }
  // Dm; InputError when no sample was added.
  Eigen::Vector3d offset() const;

 private:
  Eigen::Vector3d sum_ = Eigen::Vector3d::Zero();
  size_t n_ = 0;
};

}  // namespace onetip::devices
