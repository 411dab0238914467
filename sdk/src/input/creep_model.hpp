// input/creep_model.hpp — the pad's silicone as a standard linear solid, seen
// from the markers: what part of the field is the gel's delayed (creep) part.
//
// A standard linear solid under a load history creeps with one retardation
// time tau_c and a gain c (c = r / (1 - r) for a relaxed fraction r of the
// modulus): the surface displacement is u = u_e + v, u_e the elastic
// displacement the finger's pose causes now (what an elastic pad would show)
// and v the delayed part,
//   dv/dt = (c u_e - v) / tau_c
// per marker and per component (S, mm). Over a frame interval dt with u_e held
// over the frame and a = exp(-dt / tau_c) this steps exactly as
//   v_k = a v_{k-1} + (1 - a) c u_e,k.
// The markers measure u_k = u_e,k + v_k, so with u_e,k = u_k - v_k:
//   v_k = (a v_{k-1} + (1 - a) c u_k) / (1 + (1 - a) c)
// a causal inversion that needs only the measured field and the last v: it
// neither amplifies the noise (v is a low-pass of u) nor needs to know what
// the finger does. A held finger (u_e constant) then reads constant, and once
// the finger has left (u_e = 0) v decays as a v_{k-1}, the recovery
// input/gel_recovery.hpp follows. The parameters are the gel's, measured
// from a held press by input/gel_creep.hpp.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace onetip::input {

struct CreepModel {
  double tau_c_s = 0;  // retardation time tau_c, s (> 0 when measured)
  double gain = 0;     // c = r / (1 - r), dimensionless (> 0 when measured)
  bool measured() const { return tau_c_s > 0 && gain > 0; }
  // In the terms of a material's datasheet (and of the simulator's `viscoelastic` option): the relaxed
  // fraction r = c / (1 + c) of the modulus and the relaxation time tau = tau_c (1 - r), s.
  double relaxedFraction() const { return gain / (1 + gain); }
  double relaxationTime() const { return tau_c_s * (1 - relaxedFraction()); }
  // One line for a user: what was measured, in those terms.
  std::string describe() const;
  // One frame of dt seconds: v (S, mm per marker) advanced with the measured displacements u (p - rest, S, mm);
  // markers not valid in u keep their v decaying as without load.
  void step(std::vector<Eigen::Vector3d>& v, const std::vector<Eigen::Vector3d>& u,
            const std::vector<std::uint8_t>& valid, double dt) const;
};

}  // namespace onetip::input
