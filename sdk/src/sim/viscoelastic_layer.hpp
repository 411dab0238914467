// sim/viscoelastic_layer.hpp — the pad's silicone as a standard linear solid
// (SLS, Zener): a held press creeps and, after release, the surface recovers
// over seconds instead of at once.
//
// Material: relaxation modulus E(t) = E0 (1 - r (1 - exp(-t / tau))), with r
// the relaxed fraction (`relaxation`, E_inf = (1 - r) E0) and tau the
// relaxation time (`time_s`). Its creep compliance (the strain under a held
// unit stress) is the SLS's
//   J(t) E0 = 1 + c (1 - exp(-t / tau_c)),  c = r / (1 - r),  tau_c = tau / (1 - r)
// (the retardation time is longer than the relaxation time by E0 / E_inf).
//
// Use on the contact model: the contact model (sim/contact_model.hpp) solves
// the quasi-static problem with the instantaneous modulus E0; its
// displacement u_e(t) of every lattice node (P, mm) stands for the load the
// finger applies (a finger held at constant force, as a hand presses). The
// correspondence principle for a load history (Lee & Radok) then gives the
// viscoelastic surface displacement as u = J * d(E0 u_e):
//   u(t) = u_e(t) + v(t),   dv/dt = (c u_e(t) - v) / tau_c,
// v the delayed (viscous) part, per node and per component. Exact while the
// contact area does not shrink; on unloading it is the model's definition
// (the contact mechanics are not re-solved with the relaxed modulus: the
// delayed part is superposed on the elastic solution, so under a held pose
// the contact region sinks c (1 - exp(-t / tau_c)) x deeper than the
// indenter, as a finger held at constant force would follow it).
// Discretisation, exact for u_e held at its new value over each step
// (t_{k-1}, t_k]: with a = exp(-dt / tau_c),
//   v_k = a v_{k-1} + (1 - a) c u_e(t_k).
// So a press that steps to a held u_e at frame 0 gives exactly
// u(t_k) = u_e (1 + c (1 - exp(-t_k / tau_c))), and after a release at frame
// m (u_e = 0 from then on) u(t_k) = v_m exp(-(t_k - t_m) / tau_c): the
// surface recovers while no indenter touches it.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace onetip::sim {

struct ViscoelasticOptions {
  double relaxation = 0;   // r: relaxed fraction of the modulus, 0..0.6 (0: purely elastic, off)
  double time_s = 1.0;     // tau: relaxation time, 0.01..60 s
  bool enabled() const { return relaxation > 0; }
  double creepGain() const { return relaxation / (1 - relaxation); }        // c
  double retardationTime() const { return time_s / (1 - relaxation); }     // tau_c, s
  void validate() const;   // throws InputError naming the bad field
};

class ViscoelasticLayer {
 public:
  ViscoelasticLayer(const ViscoelasticOptions& options, int nodes);
  // Advances by dt >= 0 s with the elastic displacements u_e (one per node,
  // held over the step) and returns the total displacements u = u_e + v.
  const std::vector<Eigen::Vector3d>& advance(const std::vector<Eigen::Vector3d>& elastic, double dt);
  const std::vector<Eigen::Vector3d>& total() const { return total_; }

 private:
  ViscoelasticOptions options_;
  std::vector<Eigen::Vector3d> delayed_, total_;
};

}  // namespace onetip::sim
