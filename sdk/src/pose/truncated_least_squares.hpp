// pose/truncated_least_squares.hpp — stick weights by graduated non-convexity
// on a truncated least-squares cost (Yang, Antonante, Tzoumas and Carlone,
// "Graduated non-convexity for robust spatial perception", RA-L 2020).
//
// A marker sticks when its residual r_i against its anchor carried by the
// motion is what a sticking marker shows. The truncated cost rho(r^2) =
// min(r^2, cbar^2) charges a marker that does not (it slips) a fixed price
// cbar^2 whatever it does, so sticking markers decide the motion and slipping
// ones drop out. With r_i in units of a sticking marker's per-axis sd
// (pose/weighted_increment.hpp: two measurements' noise, which the sensor
// measures at rest, and the marker layer's share of its travel), r^2 is
// chi-square with 3 degrees of freedom and cbar^2 = chi2_3(q), q a false-slip
// rate: nothing is tuned.
//
// The truncated cost is not convex. GNC replaces it by the surrogate
//   rho_mu(r^2) = r^2                                       r^2 <= mu/(mu+1) cbar^2
//               = 2 cbar |r| sqrt(mu(mu+1)) - mu (cbar^2 + r^2)   in between
//               = cbar^2                                    r^2 >= (mu+1)/mu cbar^2
// which is convex for mu -> 0 and the truncated cost for mu -> inf, and
// alternates a weighted least-squares solve with the weights
//   w_i = 1, cbar sqrt(mu(mu+1)) / |r_i| - mu, 0   on the same three intervals,
// starting at mu_0 = cbar^2 / (2 max r^2 - cbar^2) and growing mu by a factor
// each round until every weight is 0 or 1.
#pragma once

#include <vector>

namespace onetip::pose {

// mu_0 for the largest squared residual of the first (all-weights-one) solve; 0 when every
// residual is already within the bound (nothing to graduate).
double gncInitialMu(double max_r2, double cbar2);

// The GNC-TLS weight of a residual r^2 at mu (see above).
double gncWeight(double r2, double cbar2, double mu);

// Whether the weights have settled on 0 or 1 (within `tolerance`).
bool gncWeightsBinary(const std::vector<double>& weights, double tolerance = 1e-3);

}  // namespace onetip::pose
