// devices/wire_device_geometry.hpp — the 3-DoF wire-driven fingertip device
// of the thesis (Sec. 2.2.2, Eq. 2.3-2.9).
//
// Body frame {sb} (mm): origin at the centre of the body triangle above the
// nail, z up (away from the finger pad), x to the finger's right, y towards
// the fingertip. Body vertices a_i (where the motors pull the cables) and
// plate vertices b_i (plate frame, origin at the plate centre) lie on circles
// of radius body_radius_mm and plate_radius_mm at the angles 90, 210 and 330
// deg. The plate centre is at h = [0, 0, -h0 + hz] (h0: initial height, hz:
// fingertip deformation), its rotation relative to the body is R (from the
// two IMUs). Then
//   l_i = a_i - (R b_i + h)            (Eq. 2.4, plate vertex -> body vertex)
//   d_i = l_i / |l_i|,   G = [d1 d2 d3]                  (Eq. 2.3)
//   x_i = L0_i - |l_i|   spring compression, L0_i = |l_i| at R = I, hz = 0
//   f   = G (u - k x)    the force the plate applies to the finger (Eq. 2.7),
//                        u the cable tensions (N), k the spring rate (N/mm)
// and the fingertip's second-order stiffness f_fsr = k_f hz^2 (Eq. 2.5).
// The cables slant inwards (plate radius < body radius), so G is invertible.
#pragma once

#include <Eigen/Core>
#include <array>

namespace onetip::devices {

struct WireDeviceGeometry {
  double body_radius_mm = 14.0;
  double plate_radius_mm = 7.0;
  double initial_height_mm = 14.0;  // h0
  double spring_n_per_mm = 0.2;     // k (thesis: 0.2 N/mm springs)
  double fingertip_k = 0.5;         // k_f, N/mm^2
  void validate() const;            // throws InputError naming the bad field

  Eigen::Vector3d bodyVertex(int i) const;   // a_i
  Eigen::Vector3d plateVertex(int i) const;  // b_i, plate frame
  // hz from the FSR reading (Eq. 2.5 inverted), 0 for no force.
  double deformationFromForce(double f_fsr_n) const;
};

struct WireConfiguration {
  Eigen::Matrix3d G;             // columns d_i
  Eigen::Vector3d x;             // spring compressions, mm
  Eigen::Vector3d length;        // |l_i|, mm
  std::array<Eigen::Vector3d, 3> lever;  // R b_i: vertex relative to the plate centre
};

// The cable directions and spring compressions for plate rotation R and deformation hz.
WireConfiguration wireConfiguration(const WireDeviceGeometry& g, const Eigen::Matrix3d& R, double hz_mm);

}  // namespace onetip::devices
