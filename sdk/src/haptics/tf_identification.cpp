#include "haptics/tf_identification.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>

#include "core/error.hpp"

namespace onetip::haptics {

namespace {
constexpr int kOrder = kVibrationOrder;
constexpr int kUnknowns = 2 * kOrder + 1;

// Least squares of y[k] = -sum a_i y[k-i] + sum b_j u[k-j] (zero history).
TransferFunction equationErrorFit(const std::vector<double>& u, const std::vector<double>& y) {
  const auto n = static_cast<Eigen::Index>(u.size());
  Eigen::MatrixXd phi(n, kUnknowns);
  Eigen::VectorXd target(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    for (int i = 1; i <= kOrder; ++i) phi(k, i - 1) = k - i >= 0 ? -y[static_cast<size_t>(k - i)] : 0.0;
    for (int j = 0; j <= kOrder; ++j) phi(k, kOrder + j) = k - j >= 0 ? u[static_cast<size_t>(k - j)] : 0.0;
    target(k) = y[static_cast<size_t>(k)];
  }
  const Eigen::VectorXd theta = phi.colPivHouseholderQr().solve(target);
  TransferFunction tf;
  tf.a[0] = 1.0;
  for (int i = 1; i <= kOrder; ++i) tf.a[static_cast<size_t>(i)] = theta(i - 1);
  for (int j = 0; j <= kOrder; ++j) tf.b[static_cast<size_t>(j)] = theta(kOrder + j);
  return tf;
}

// Mirrors poles outside the unit circle to 1 / conj(p), keeping a[0] = 1.
void stabilize(TransferFunction& tf) {
  if (tf.stable()) return;
  Eigen::Matrix<double, kOrder, kOrder> companion;
  companion.setZero();
  for (int i = 0; i < kOrder; ++i) companion(0, i) = -tf.a[static_cast<size_t>(i + 1)];
  for (int i = 1; i < kOrder; ++i) companion(i, i - 1) = 1.0;
  const Eigen::Matrix<std::complex<double>, kOrder, 1> poles = companion.eigenvalues();
  std::array<std::complex<double>, kOrder + 1> poly{};
  poly[0] = 1.0;
  for (int p = 0; p < kOrder; ++p) {
    std::complex<double> root = poles(p);
    if (std::abs(root) >= 1.0) root = 0.999 / std::conj(root);
    for (int i = p + 1; i >= 1; --i) poly[static_cast<size_t>(i)] -= root * poly[static_cast<size_t>(i - 1)];
  }
  for (size_t i = 0; i <= kOrder; ++i) tf.a[i] = poly[i].real();
}

std::vector<double> allPole(const TransferFunction& tf, const std::vector<double>& x) {
  TransferFunction inverse_a;
  inverse_a.a = tf.a;
  inverse_a.b[0] = 1.0;
  return filterSignal(inverse_a, x);
}

}  // namespace

void SweepOptions::validate() const {
  if (!(fs_hz > 0.0)) throw InputError("SweepOptions.fs_hz: must be positive");
  if (!(f0_hz > 0.0 && f1_hz > f0_hz && f1_hz < fs_hz / 2.0))
    throw InputError("SweepOptions.f1_hz: need 0 < f0_hz < f1_hz < fs_hz / 2");
  if (!(duration_s > 0.0 && duration_s <= 60.0)) throw InputError("SweepOptions.duration_s: must be in (0, 60]");
}

void IdentificationOptions::validate() const {
  if (max_iterations < 0 || max_iterations > 1000)
    throw InputError("IdentificationOptions.max_iterations: must be in 0..1000");
  if (!(tolerance > 0.0)) throw InputError("IdentificationOptions.tolerance: must be positive");
}

std::vector<double> sweptSine(const SweepOptions& o) {
  o.validate();
  const auto n = static_cast<size_t>(std::lround(o.duration_s * o.fs_hz));
  const double rate = std::log(o.f1_hz / o.f0_hz) / o.duration_s;
  std::vector<double> u(n);
  for (size_t k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) / o.fs_hz;
    u[k] = std::sin(2.0 * M_PI * o.f0_hz / rate * (std::exp(rate * t) - 1.0));
  }
  return u;
}

std::vector<double> filterSignal(const TransferFunction& tf, const std::vector<double>& u) {
  IirFilter filter(tf);
  std::vector<double> y(u.size());
  for (size_t k = 0; k < u.size(); ++k) y[k] = filter.process(u[k]);
  return y;
}

IdentificationResult identifyTransferFunction(const std::vector<double>& u, const std::vector<double>& y,
                                              const IdentificationOptions& options) {
  options.validate();
  if (u.size() != y.size()) throw InputError("identifyTransferFunction: input and output lengths differ");
  if (u.size() < 100) throw InputError("identifyTransferFunction: need at least 100 samples");
  IdentificationResult r;
  r.tf = equationErrorFit(u, y);
  stabilize(r.tf);
  for (int it = 0; it < options.max_iterations; ++it) {
    TransferFunction next = equationErrorFit(allPole(r.tf, u), allPole(r.tf, y));
    stabilize(next);
    double change = 0.0, size = 0.0;
    for (size_t i = 0; i <= kOrder; ++i) {
      change += std::pow(next.a[i] - r.tf.a[i], 2) + std::pow(next.b[i] - r.tf.b[i], 2);
      size += next.a[i] * next.a[i] + next.b[i] * next.b[i];
    }
    r.tf = next;
    r.iterations = it + 1;
    if (std::sqrt(change / size) < options.tolerance) {
      r.converged = true;
      break;
    }
  }
  const std::vector<double> fitted = filterSignal(r.tf, u);
  double sq = 0.0;
  for (size_t k = 0; k < y.size(); ++k) sq += std::pow(y[k] - fitted[k], 2);
  r.residual_rms = std::sqrt(sq / static_cast<double>(y.size()));
  return r;
}

}  // namespace onetip::haptics
