// haptics/vibration_channel.hpp — the run-time vibration channel (da Vinci
// paper, Algorithm 1): the sensed AC pressure signal (2200 Hz) filtered by
// the transfer function of the configuration the renderer selected, with
// click-free switching between configurations.
//
// Switching: the new configuration's filter is first run over the last
// `warmup_samples` inputs (kept in a ring buffer) so that its state is what it
// would be had it been running all along; the output then crossfades from the
// old filter to the new one over `fade_samples` with a raised-cosine weight
//   y = (1 - w) y_old + w y_new,   w = (1 - cos(pi k / fade)) / 2,
// both filters fed the same input. A selection arriving during a fade waits
// for it to end (at most fade_samples). Defaults: 256 samples (116 ms, > 4
// time constants of the plants of vibration_plant.hpp) and 22 samples (10 ms).
#pragma once

#include <optional>
#include <vector>

#include "haptics/transfer_function.hpp"

namespace onetip::haptics {

struct VibrationChannelOptions {
  int warmup_samples = 256;
  int fade_samples = 22;
  void validate() const;  // throws InputError naming the bad field
};

class VibrationChannel {
 public:
  explicit VibrationChannel(const TransferFunction& initial, const VibrationChannelOptions& options = {});
  // Selects the filter for the following samples.
  void select(const TransferFunction& tf);
  // One AC sample in, one filtered sample out.
  double process(double x);
  bool fading() const noexcept { return fade_position_ >= 0; }

 private:
  void startFade(const TransferFunction& tf);

  VibrationChannelOptions options_;
  IirFilter current_;
  IirFilter previous_;
  int fade_position_ = -1;  // -1: not fading
  std::optional<TransferFunction> pending_;
  std::vector<double> history_;
  size_t history_next_ = 0;
  size_t history_count_ = 0;
};

}  // namespace onetip::haptics
