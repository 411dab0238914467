#include "wire_plant.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>

#include "core/rotation.hpp"

namespace onetip::devices::testing {

WirePlant::WirePlant(const WireDeviceGeometry& geometry, const WirePlantOptions& options)
    : g_(geometry), o_(options), rng_(options.seed) {}

Eigen::Matrix3d WirePlant::trueRotation() const { return rotationFromYawPitchRoll(0.0, q_(2), q_(1)); }

Eigen::Vector3d WirePlant::residual(const Eigen::Vector3d& q) const {
  const Eigen::Matrix3d R = rotationFromYawPitchRoll(0.0, q(2), q(1));
  const WireConfiguration c = wireConfiguration(g_, R, q(0));
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), torque = Eigen::Vector3d::Zero();
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d F = (tension_(i) - g_.spring_n_per_mm * c.x(i)) * c.G.col(i);
    force += F;
    torque += c.lever[i].cross(F);
  }
  const double hz = std::max(q(0), 0.0);
  return {force.z() - g_.fingertip_k * hz * hz, torque.x() - o_.rotational_stiffness_nmm_per_rad * q(2),
          torque.y() - o_.rotational_stiffness_nmm_per_rad * q(1)};
}

void WirePlant::solveEquilibrium() {
  for (int iter = 0; iter < 30; ++iter) {
    const Eigen::Vector3d r = residual(q_);
    Eigen::Matrix3d J;
    for (int j = 0; j < 3; ++j) {
      Eigen::Vector3d dq = Eigen::Vector3d::Zero();
      dq(j) = 1e-7;
      J.col(j) = (residual(q_ + dq) - r) / 1e-7;
    }
    const Eigen::Vector3d step = J.partialPivLu().solve(-r);
    q_ += step;
    if (step.norm() < 1e-11) break;
  }
}

void WirePlant::advance(const Eigen::Vector3d& command, double dt_s, int substeps) {
  const double h = dt_s / substeps;
  for (int s = 0; s < substeps; ++s) {
    tension_ += (command - tension_) * (1.0 - std::exp(-h / o_.motor_time_constant_s));
    solveEquilibrium();
  }
}

Eigen::Vector3d WirePlant::contactForce() const {
  const WireConfiguration c = wireConfiguration(g_, trueRotation(), q_(0));
  return c.G * (tension_ - g_.spring_n_per_mm * c.x);
}

double WirePlant::normalForce() const {
  const double hz = std::max(q_(0), 0.0);
  return g_.fingertip_k * hz * hz;
}

double WirePlant::rollDeg() const { return q_(1) * kDegPerRad; }
double WirePlant::pitchDeg() const { return q_(2) * kDegPerRad; }

Eigen::Matrix3d WirePlant::measuredRotation() {
  std::normal_distribution<double> n(0.0, o_.imu_noise_deg * kRadPerDeg);
  return trueRotation() * rotationFromYawPitchRoll(n(rng_), n(rng_), n(rng_));
}

double WirePlant::measuredFsr() {
  std::normal_distribution<double> n(0.0, o_.fsr_noise_n);
  return std::max(0.0, normalForce() + n(rng_));
}

}  // namespace onetip::devices::testing
