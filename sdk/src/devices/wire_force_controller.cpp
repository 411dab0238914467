#include "devices/wire_force_controller.hpp"

#include <Eigen/LU>

#include "core/error.hpp"

namespace onetip::devices {

void WireControllerOptions::validate() const {
  if (!(lambda > 0.0 && lambda < 1000.0)) throw InputError("WireControllerOptions.lambda: must be in (0, 1000)");
  if (!(min_tension_n >= 0.0 && max_tension_n > min_tension_n && max_tension_n < 100.0))
    throw InputError("WireControllerOptions.min_tension_n/max_tension_n: need 0 <= min < max < 100");
}

WireForceController::WireForceController(const WireDeviceGeometry& geometry, const WireControllerOptions& options)
    : geometry_(geometry), options_(options) {
  geometry_.validate();
  options_.validate();
}

void WireForceController::reset() {
  u_.setZero();
  estimate_.setZero();
  previous_.reset();
}

const Eigen::Vector3d& WireForceController::step(const Eigen::Vector3d& fd, const Eigen::Matrix3d& R_measured,
                                                 double f_fsr_n, double dt_s) {
  const double k = geometry_.spring_n_per_mm;
  const WireConfiguration now = wireConfiguration(geometry_, R_measured, geometry_.deformationFromForce(f_fsr_n));
  const Eigen::Vector3d slack = u_ - k * now.x;
  estimate_ = now.G * slack;
  Eigen::Matrix3d G_dot = Eigen::Matrix3d::Zero();
  Eigen::Vector3d x_dot = Eigen::Vector3d::Zero();
  if (previous_) {
    G_dot = (now.G - previous_->G) / dt_s;
    x_dot = (now.x - previous_->x) / dt_s;
  }
  const Eigen::Vector3d u_dot = now.G.partialPivLu().solve(-options_.lambda * (estimate_ - fd) - G_dot * slack) + k * x_dot;
  u_ = (u_ + dt_s * u_dot).cwiseMax(options_.min_tension_n).cwiseMin(options_.max_tension_n);
  previous_ = now;
  return u_;
}

}  // namespace onetip::devices
