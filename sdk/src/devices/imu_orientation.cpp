#include "devices/imu_orientation.hpp"

#include <Eigen/Geometry>

#include "core/error.hpp"

namespace onetip::devices {

Eigen::Matrix3d orientationFromAccelMag(const Eigen::Vector3d& accel, const Eigen::Vector3d& mag) {
  if (!(accel.allFinite() && mag.allFinite()) || accel.norm() < 1e-9) throw InputError("IMU: no gravity reading");
  const Eigen::Vector3d up = accel.normalized();
  const Eigen::Vector3d horizontal = mag - mag.dot(up) * up;
  if (horizontal.norm() < 1e-6 * std::max(1.0, mag.norm())) throw InputError("IMU: magnetic field parallel to gravity");
  const Eigen::Vector3d north = horizontal.normalized();
  Eigen::Matrix3d R;
  R.row(0) = north.transpose();
  R.row(1) = up.cross(north).transpose();
  R.row(2) = up.transpose();
  return R;
}

void MagnetometerOffsetCalibration::add(const Eigen::Vector3d& distorted, const Eigen::Vector3d& undistorted) {
  if (!(distorted.allFinite() && undistorted.allFinite())) throw InputError("magnetometer calibration: non-finite reading");
  sum_ += distorted - undistorted;
  ++n_;
}

Eigen::Vector3d MagnetometerOffsetCalibration::offset() const {
  if (n_ == 0) throw InputError("magnetometer calibration: no samples");
  return sum_ / static_cast<double>(n_);
}

}  // namespace onetip::devices
