// input/input_filter.hpp — smoothing of the 6-D signal, per axis.
//
// moving_average: the paper's filter, the mean of the last `window` samples
//   (window 5: a delay of (window - 1) / 2 = 2 frames).
// one_euro: the 1-euro filter (Casiez et al., CHI 2012), a first-order
//   low-pass whose cut-off rises with speed: fc = min_cutoff_hz + beta * |dx/dt|,
//   alpha = 1 / (1 + 1 / (2 pi fc dt)); the speed itself is low-passed at
//   derivative_cutoff_hz. Little lag while moving, strong smoothing at rest.
// Units follow the signal (mm and degrees); time in seconds.
#pragma once

#include <array>
#include <deque>
#include <memory>

#include "onetip/types.hpp"

namespace onetip::input {

enum class FilterKind : std::uint8_t { none = 0, moving_average, one_euro };

struct InputFilterOptions {
  FilterKind kind = FilterKind::none;
  int window = 5;                      // moving_average
  double min_cutoff_hz = 1.0;          // one_euro
  double beta = 0.05;                  // one_euro, per (unit / s)
  double derivative_cutoff_hz = 1.0;   // one_euro
  void validate() const;               // throws InputError naming the bad field
};

class InputFilter {
 public:
  virtual ~InputFilter() = default;
  virtual Input6 apply(const Input6& x, double t) = 0;
  virtual void reset() = 0;
};

class MovingAverageFilter final : public InputFilter {
 public:
  explicit MovingAverageFilter(int window);
  Input6 apply(const Input6& x, double t) override;
  void reset() override { samples_.clear(); }

 private:
  int window_;
  std::deque<std::array<double, 6>> samples_;
};

class OneEuroFilter final : public InputFilter {
 public:
  OneEuroFilter(double min_cutoff_hz, double beta, double derivative_cutoff_hz);
  Input6 apply(const Input6& x, double t) override;
  void reset() override { started_ = false; }

 private:
  double min_cutoff_, beta_, d_cutoff_;
  bool started_ = false;
  double t_prev_ = 0;
  std::array<double, 6> x_prev_{}, dx_prev_{};
};

// nullptr for FilterKind::none.
std::unique_ptr<InputFilter> makeInputFilter(const InputFilterOptions& options);

}  // namespace onetip::input
