// haptics/transfer_function.hpp — a discrete-time transfer function of order
// 6 (6 poles, 6 zeros), the vibration channel's per-configuration model
// (da Vinci paper, Sec. III-B: c_* in R^14 = b0..b6, a0..a6 with a0 = 1).
//
//   H(z) = (b0 + b1 z^-1 + ... + b6 z^-6) / (1 + a1 z^-1 + ... + a6 z^-6)
// at sampling rate fs (the BioTac's AC pressure channel: 2200 Hz).
// IirFilter runs it in transposed direct form II, in double.
#pragma once

#include <array>
#include <complex>

namespace onetip::haptics {

constexpr int kVibrationOrder = 6;
constexpr double kVibrationRateHz = 2200.0;

struct TransferFunction {
  std::array<double, kVibrationOrder + 1> b{};  // numerator
  std::array<double, kVibrationOrder + 1> a{};  // denominator, a[0] = 1
  // H(e^{j 2 pi f / fs})
  std::complex<double> response(double f_hz, double fs_hz = kVibrationRateHz) const;
  double gainDb(double f_hz, double fs_hz = kVibrationRateHz) const;
  // All poles strictly inside the unit circle.
  bool stable() const;
};

class IirFilter {
 public:
  IirFilter() = default;
  explicit IirFilter(const TransferFunction& tf) : tf_(tf) {}
  double process(double x);
  void reset() { state_.fill(0.0); }
  const TransferFunction& transferFunction() const noexcept { return tf_; }

 private:
  TransferFunction tf_;
  std::array<double, kVibrationOrder> state_{};
};

}  // namespace onetip::haptics
