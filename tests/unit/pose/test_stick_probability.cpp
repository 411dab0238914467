// The stick probability (contact/stick_probability.hpp) against the mixture's
// closed form: where the two densities are equal it is one half.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "contact/stick_probability.hpp"

using namespace onetip::contact;

TEST(StickProbability, OneHalfWhereTheStickAndSlipDensitiesMeet) {
  const double threshold = 0.01, reach = 1.5;
  const double s = threshold * kStickScatterPerThreshold;
  // N(d) = U  <=>  d^2 = 2 s^2 (log N(0) - log U), N(0) = (2 pi s^2)^(-3/2), U = 3 / (4 pi R^3).
  const double log_n0 = -1.5 * std::log(2 * std::numbers::pi * s * s);
  const double log_u = std::log(3 / (4 * std::numbers::pi * reach * reach * reach));
  const double d_half = std::sqrt(2 * s * s * (log_n0 - log_u));
  EXPECT_NEAR(stickProbability(d_half, threshold, reach), 0.5, 1e-9);
  EXPECT_NEAR(d_half / threshold, 1.75, 0.01);  // as the header states
}

TEST(StickProbability, FallsWithTheDriftAndStaysAProbability) {
  double last = 2;
  for (double d = 0; d < 0.1; d += 0.001) {
    const double p = stickProbability(d, 0.01, 1.5);
    EXPECT_GE(p, 0.0);
    EXPECT_LE(p, 1.0);
    EXPECT_LE(p, last);
    last = p;
  }
  EXPECT_GT(stickProbability(0.0, 0.01, 1.5), 0.999);
  EXPECT_GT(stickProbability(0.01, 0.01, 1.5), 0.99);  // at the slip threshold: still a sticking marker's scatter
  EXPECT_LT(stickProbability(0.03, 0.01, 1.5), 1e-6);
  EXPECT_EQ(stickProbability(5.0, 0.01, 1.5), 0.0);    // far beyond: no underflow to NaN
}
