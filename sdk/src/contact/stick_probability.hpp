// contact/stick_probability.hpp — the probability that a marker sticks to the
// finger, from its drift off its anchor.
//
// A two-component mixture on the drift d = |p_i - T a_i| (mm) of one frame
// (contact/stick_slip_classifier.hpp):
//  - stick: the drift is the marker's scatter about the finger's rigid motion,
//    isotropic Gaussian with per-axis sd s, so that a sticking marker stays
//    below the slip threshold with probability 0.99: s = threshold /
//    sqrt(chi2_3(0.99)) = threshold / 3.368;
//  - slip: the marker may have moved anywhere within the largest step the
//    finger makes in a frame (radius R, mm): uniform density 3 / (4 pi R^3);
//  - equal priors (nothing else is known about a marker that is in contact).
// P(stick | d) = N(d) / (N(d) + U), N the 3-D Gaussian density at offset d.
// With the defaults (threshold 0.01 mm, R 1.5 mm) the probability is 0.5 at a
// drift of 1.75 thresholds; it falls from 0.99 to 0.005 between 1.5 and 2.0.
#pragma once

namespace onetip::contact {

constexpr double kStickScatterPerThreshold = 1.0 / 3.368;  // s / slip threshold (chi-square, 3 dof, 0.99)

// drift_mm >= 0; slip_threshold_mm > 0; reach_mm > 0. Returns a probability in [0, 1].
double stickProbability(double drift_mm, double slip_threshold_mm, double reach_mm);

}  // namespace onetip::contact
