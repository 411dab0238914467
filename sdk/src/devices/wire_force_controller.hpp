// devices/wire_force_controller.hpp — the contact-force controller of the
// 3-DoF wire device (thesis Eq. 2.10-2.11), integrated to cable tensions.
//
// With the force estimate f = G (u - k x) (wire_device_geometry.hpp) built
// from the measured plate rotation R (IMUs) and deformation hz (FSR, Eq. 2.5),
// the error dynamics (f' - fd') = -lambda (f - fd) give
//   u' = G^-1 [ fd' - lambda (f - fd) - G' (u - k x) ] + k x'      (Eq. 2.11)
// with fd' neglected (as in the thesis) and G', x' taken as finite
// differences of successive measurements. u is integrated with explicit
// Euler and kept in [min_tension_n, max_tension_n] (cables only pull), which
// also bounds the integrator. For a first-order error decay the 10-90 % rise
// time is ln(9) / lambda: lambda = 11 /s gives the thesis' ~0.2 s.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "devices/wire_device_geometry.hpp"

namespace onetip::devices {

struct WireControllerOptions {
  double lambda = 11.0;          // 1/s
  double min_tension_n = 0.0;
  double max_tension_n = 3.0;
  void validate() const;         // throws InputError naming the bad field
};

class WireForceController {
 public:
  WireForceController(const WireDeviceGeometry& geometry, const WireControllerOptions& options = {});
  // One step of dt seconds towards the desired force fd (N, body frame), given
  // the measured plate rotation and FSR force. Returns the cable tensions u (N).
  const Eigen::Vector3d& step(const Eigen::Vector3d& fd, const Eigen::Matrix3d& R_measured, double f_fsr_n,
                              double dt_s);
  // f = G (u - k x) at the last step (N).
  const Eigen::Vector3d& estimatedForce() const noexcept { return estimate_; }
  const Eigen::Vector3d& tensions() const noexcept { return u_; }
  void reset();  // u = 0, forget the previous measurement

 private:
  WireDeviceGeometry geometry_;
  WireControllerOptions options_;
  Eigen::Vector3d u_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d estimate_ = Eigen::Vector3d::Zero();
  std::optional<WireConfiguration> previous_;
};

}  // namespace onetip::devices
