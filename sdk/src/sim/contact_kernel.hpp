// sim/contact_kernel.hpp — the surface Green's functions of the two contact
// models (PadOptions::contact_model) on the node lattice.
//
// A traction on node j (spacing h, mm) displaces node i by K(r_ij) times
// (c_t q_x, c_t q_y, -p); tractions are in units of compliance (mm), so only
// the kernel's shape and c_t matter for the kinematics.
//   halfspace (incompressible elastic layer of thickness T; Boussinesq's point
//     load damped over T, Goodman's uncoupling, nu = 0.5):
//       K(r) = h^2 exp(-r / T) / r,  K(0) = 4 ln(1 + sqrt 2) h (exact cell integral),
//       c_t = (2 - nu) / (2 - 2 nu) = 1.5;
//   foundation (Pasternak: Winkler springs coupled by a shear layer of
//     length l = sqrt(G_p / k), l = T / sqrt(3) unless set; nu = 0):
//       K(r) = h^2 K0(r / l) / l,  K(0) = the integral of K0(|y| / l) / l over
//       one cell (midpoint rule on a 64 x 64 sub-grid; K0 has an integrable
//       log singularity), c_t = 1.0.
// The foundation kernel is log-singular and decays as exp(-r / l) / sqrt(r):
// the surface dips steeply at the contact edge and hardly at all a few l away,
// where the halfspace kernel's 1/r tail still pulls; its pressure is flatter.
#pragma once

#include <vector>

#include "sim/pad.hpp"

namespace onetip::sim {

// Tangential-to-normal compliance ratio c_t of a model.
double tangentialComplianceRatio(ContactModelKind kind) noexcept;
// Kernel value at lattice offset (da, db) in nodes, spacing h (mm).
double contactKernel(const PadOptions& pad, double h, int da, int db);

}  // namespace onetip::sim
