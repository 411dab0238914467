#include "haptics/transfer_function.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace onetip::haptics {

std::complex<double> TransferFunction::response(double f_hz, double fs_hz) const {
  const std::complex<double> z_inv = std::polar(1.0, -2.0 * M_PI * f_hz / fs_hz);
  std::complex<double> num = 0.0, den = 0.0, p = 1.0;
  for (int i = 0; i <= kVibrationOrder; ++i) {
    num += b[static_cast<size_t>(i)] * p;
    den += a[static_cast<size_t>(i)] * p;
    p *= z_inv;
  }
  return num / den;
}

double TransferFunction::gainDb(double f_hz, double fs_hz) const {
  return 20.0 * std::log10(std::abs(response(f_hz, fs_hz)));
}

bool TransferFunction::stable() const {
  Eigen::Matrix<double, kVibrationOrder, kVibrationOrder> companion;
  companion.setZero();
  for (int i = 0; i < kVibrationOrder; ++i) companion(0, i) = -a[static_cast<size_t>(i + 1)] / a[0];
  for (int i = 1; i < kVibrationOrder; ++i) companion(i, i - 1) = 1.0;
  const auto poles = companion.eigenvalues();
  for (int i = 0; i < kVibrationOrder; ++i)
    if (std::abs(poles(i)) >= 1.0) return false;
  return true;
}

double IirFilter::process(double x) {
  const double y = tf_.b[0] * x + state_[0];
  for (size_t i = 0; i + 1 < kVibrationOrder; ++i) state_[i] = tf_.b[i + 1] * x - tf_.a[i + 1] * y + state_[i + 1];
  state_[kVibrationOrder - 1] = tf_.b[kVibrationOrder] * x - tf_.a[kVibrationOrder] * y;
  return y;
}

}  // namespace onetip::haptics
