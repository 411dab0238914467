// sim/rest_drift.hpp — the pad's rest state drifting slowly over minutes, as
// the silicone and its housing warm up (thermal expansion) and settle.
//
// A uniform lateral expansion about the pad's centre axis plus an offset,
// both approaching their final values with one time constant (a first-order
// thermal response to a step in temperature at t = 0):
//   g(t) = 1 - exp(-t / time_s)
//   x' = (1 + expansion g(t)) x + offset_x g(t)
//   y' = (1 + expansion g(t)) y + offset_y g(t)
//   z' = z + offset_z g(t)
// applied to every rest point of the pad (P, mm: the marker layer's and so
// every marker's and every rendered lattice vertex's), before the contact
// displacement is added; so the field level (gt_markers.csv) and the image
// both see it. `expansion` is a strain (0.002 = 0.2 %: 0.02 mm at the outer
// markers 9.6 mm from the centre), offsets are mm. The ground truth measures
// contact against the drifted rest (sim/ground_truth.hpp), so drift alone is
// never a touch.
#pragma once

#include <Eigen/Core>

namespace onetip::sim {

struct RestDriftOptions {
  double expansion = 0;                           // final lateral strain, -0.02..0.02
  Eigen::Vector3d offset_mm = Eigen::Vector3d::Zero();  // final offset, each component -1..1 mm
  double time_s = 120;                            // time constant, 1..7200 s
  bool enabled() const { return expansion != 0 || !offset_mm.isZero(0); }
  double progress(double t) const;                // g(t)
  // The drifted position of a rest point p (P, mm) at time t (s).
  Eigen::Vector3d apply(const Eigen::Vector3d& p, double t) const;
  void validate() const;                          // throws InputError naming the bad field
};

}  // namespace onetip::sim
