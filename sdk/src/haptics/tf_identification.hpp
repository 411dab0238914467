// haptics/tf_identification.hpp — identifying a configuration's 6-pole /
// 6-zero vibration transfer function from a swept sine (da Vinci paper,
// Sec. III-B).
//
// Excitation: an exponential sweep from f0 to f1 over T seconds at fs,
//   u(t) = sin(2 pi f0 T / ln(f1/f0) * (exp(t ln(f1/f0) / T) - 1)),
// by default 1 -> 1000 Hz over 2 s at 2200 Hz (4400 samples).
// Fit, with the plant at rest before the sweep (zero initial conditions):
//   1. equation error (ARX): least squares of  A(q) y = B(q) u  for the 13
//      coefficients b0..b6, a1..a6 (column-pivoted QR);
//   2. Steiglitz-McBride: repeat 1 on u and y pre-filtered by 1 / A_prev(q),
//      which converges to the output-error fit (unbiased under white output
//      noise, where plain ARX is biased); an unstable A is mirrored into the
//      unit circle (poles p -> 1 / conj(p)) before it is used as a filter.
// Stops after `max_iterations` or when the coefficients change by less than
// `tolerance` (relative).
#pragma once

#include <vector>

#include "haptics/transfer_function.hpp"

namespace onetip::haptics {

struct SweepOptions {
  double f0_hz = 1.0;
  double f1_hz = 1000.0;
  double duration_s = 2.0;
  double fs_hz = kVibrationRateHz;
  void validate() const;  // throws InputError naming the bad field
};

std::vector<double> sweptSine(const SweepOptions& options = {});

struct IdentificationOptions {
  int max_iterations = 30;  // Steiglitz-McBride iterations (0: ARX only)
  double tolerance = 1e-10;
  void validate() const;
};

struct IdentificationResult {
  TransferFunction tf;
  int iterations = 0;           // Steiglitz-McBride iterations run
  bool converged = false;
  double residual_rms = 0.0;    // rms of y - H u over the record
};

// u, y: equal length >= 100 samples. InputError otherwise.
IdentificationResult identifyTransferFunction(const std::vector<double>& u, const std::vector<double>& y,
                                              const IdentificationOptions& options = {});

// y = H u from rest.
std::vector<double> filterSignal(const TransferFunction& tf, const std::vector<double>& u);

}  // namespace onetip::haptics
