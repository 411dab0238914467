// devices/pseudo_haptics.hpp — pseudo-haptic stiffness with a cutaneous
// device (thesis Ch. 3-4), for any device that takes a normal force.
//
// The fingertip avatar is a sphere of diameter D (mm) touching a virtual
// plane (point p, outward unit normal n). With the sphere centre c,
//   dx_real = max(0, r - n.(c - p)),  r = D / 2    (penetration, mm)
// In contact (dx_real > 0) the C/D ratio scales the displacement shown on
// screen (Eq. 3.1):  dx_virtual = alpha dx_real, i.e. the avatar is drawn at
//   c_virtual = c + (1 - alpha) dx_real n;
// out of contact it is drawn where the finger is. alpha < 1 feels stiffer,
// alpha > 1 softer. The device force is (Eq. 4.1)
//   f = K dx,  K = stiffness_scale K0,  K0 = F_max / D  (N/mm)
// with dx = dx_real (Experiments 1-2) or dx_virtual (Experiment 3,
// force_from_virtual). It saturates at F_max; `saturated` tells the display
// to show it (the thesis turns the plane red).
#pragma once

#include <Eigen/Core>

namespace onetip::devices {

// Eq. 3.1 for one displacement: alpha * dx in contact, dx otherwise.
double cdScaledDisplacement(double alpha, double real_displacement_mm, bool in_contact);

struct PseudoHapticsOptions {
  double alpha = 1.0;                 // C/D ratio, > 0
  double max_device_force_n = 1.0;    // F_max
  double avatar_diameter_mm = 20.0;   // D
  double stiffness_scale = 1.0;       // K / K0
  bool force_from_virtual = false;
  void validate() const;              // throws InputError naming the bad field
  double baselineStiffness() const { return max_device_force_n / avatar_diameter_mm; }  // K0, N/mm
};

struct PseudoHapticContact {
  bool in_contact = false;
  double real_penetration_mm = 0.0;
  double virtual_penetration_mm = 0.0;
  Eigen::Vector3d avatar_centre = Eigen::Vector3d::Zero();  // where to draw the sphere
  double force_n = 0.0;               // along n, towards the finger: the device's normal force goal
  bool saturated = false;
};

class PseudoHapticPlane {
 public:
  PseudoHapticPlane(const Eigen::Vector3d& point, const Eigen::Vector3d& outward_normal,
                    const PseudoHapticsOptions& options);
  PseudoHapticContact update(const Eigen::Vector3d& fingertip_centre) const;
  const PseudoHapticsOptions& options() const noexcept { return options_; }

 private:
  Eigen::Vector3d point_, normal_;
  PseudoHapticsOptions options_;
};

}  // namespace onetip::devices
