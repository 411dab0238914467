#include "input/input_filter.hpp"

#include <cmath>
#include <numbers>

#include "core/option_checks.hpp"

namespace onetip::input {

void InputFilterOptions::validate() const {
  requireAtLeast("input filter: window", window, 1, "frames");
  requireAbove("input filter: min_cutoff_hz", min_cutoff_hz, 0, "Hz");
  requireAtLeast("input filter: beta", beta, 0);
  requireAbove("input filter: derivative_cutoff_hz", derivative_cutoff_hz, 0, "Hz");
}

MovingAverageFilter::MovingAverageFilter(int window) : window_(window) {
  requireAtLeast("moving average: window", window, 1, "frames");
}

Input6 MovingAverageFilter::apply(const Input6& x, double) {
  samples_.push_back(x.asArray());
  while (static_cast<int>(samples_.size()) > window_) samples_.pop_front();
  std::array<double, 6> mean{};
  for (const auto& s : samples_)
    for (size_t k = 0; k < 6; ++k) mean[k] += s[k];
  for (double& m : mean) m /= static_cast<double>(samples_.size());
  return Input6::fromArray(mean);
}

OneEuroFilter::OneEuroFilter(double min_cutoff_hz, double beta, double derivative_cutoff_hz)
    : min_cutoff_(min_cutoff_hz), beta_(beta), d_cutoff_(derivative_cutoff_hz) {}

namespace {
double smoothing(double cutoff_hz, double dt) {
  const double tau = 1.0 / (2.0 * std::numbers::pi * cutoff_hz);
  return 1.0 / (1.0 + tau / dt);
}
}  // namespace

Input6 OneEuroFilter::apply(const Input6& x, double t) {
  const auto v = x.asArray();
  const double dt = t - t_prev_;
  if (!started_ || !(dt > 0)) {
    // First sample, or a time that does not advance: pass through and restart.
    started_ = true;
    t_prev_ = t;
    x_prev_ = v;
    dx_prev_.fill(0);
    return x;
  }
  t_prev_ = t;
  const double a_d = smoothing(d_cutoff_, dt);
  for (size_t k = 0; k < 6; ++k) {
    const double dx = a_d * (v[k] - x_prev_[k]) / dt + (1 - a_d) * dx_prev_[k];
    const double a = smoothing(min_cutoff_ + beta_ * std::abs(dx), dt);
    x_prev_[k] = a * v[k] + (1 - a) * x_prev_[k];
    dx_prev_[k] = dx;
  }
  return Input6::fromArray(x_prev_);
}

std::unique_ptr<InputFilter> makeInputFilter(const InputFilterOptions& o) {
  o.validate();
  switch (o.kind) {
    case FilterKind::moving_average: return std::make_unique<MovingAverageFilter>(o.window);
    case FilterKind::one_euro: return std::make_unique<OneEuroFilter>(o.min_cutoff_hz, o.beta, o.derivative_cutoff_hz);
    case FilterKind::none: break;
  }
  return nullptr;
}

}  // namespace onetip::input
