#include "sim/contact_kernel.hpp"

#include <cmath>

namespace onetip::sim {

namespace {

double foundationLength(const PadOptions& pad) {
  return pad.foundation_length_mm > 0 ? pad.foundation_length_mm : pad.thickness_mm / std::sqrt(3.0);
}

// Integral of K0(|y| / l) / l over the cell [-h/2, h/2]^2.
double foundationSelfTerm(double h, double l) {
  constexpr int kSub = 64;
  const double step = h / kSub;
  double sum = 0;
  for (int a = 0; a < kSub; ++a)
    for (int b = 0; b < kSub; ++b) {
      const double x = -0.5 * h + (a + 0.5) * step, y = -0.5 * h + (b + 0.5) * step;
      sum += std::cyl_bessel_k(0.0, std::hypot(x, y) / l);
    }
  return sum * step * step / l;
}

}  // namespace

double tangentialComplianceRatio(ContactModelKind kind) noexcept {
  return kind == ContactModelKind::foundation ? 1.0 : 1.5;
}

double contactKernel(const PadOptions& pad, double h, int da, int db) {
  const double r = h * std::hypot(da, db);
  if (pad.contact_model == ContactModelKind::foundation) {
    const double l = foundationLength(pad);
    return r == 0 ? foundationSelfTerm(h, l) : h * h * std::cyl_bessel_k(0.0, r / l) / l;
  }
  return r == 0 ? 4.0 * std::log(1.0 + std::sqrt(2.0)) * h : h * h * std::exp(-r / pad.thickness_mm) / r;
}

}  // namespace onetip::sim
