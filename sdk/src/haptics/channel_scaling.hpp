// haptics/channel_scaling.hpp — per-channel standardisation of sensed vectors.
//
// The paper divides every channel by its standard deviation over the data set
// so that each weighs the same in the Euclidean distance: x_i = s_i / sigma_i
// (no mean is subtracted: distances do not need it). sigma_i is the population
// standard deviation of channel i over the dataset's rows, computed in double.
// A channel that never varies (sigma_i <= 1e-9 * max(1, |mean_i|)) cannot tell
// dataset points apart; it gets scale 0, so it is left out of the distance
// instead of dividing by zero. Eq. 9 errors use the same scales.
#pragma once

#include <vector>

#include "haptics/tactile_dataset.hpp"

namespace onetip::haptics {

struct ChannelScaling {
  std::vector<double> sigma;  // per channel, sensed units
  std::vector<double> scale;  // 1 / sigma, or 0 for a constant channel

  static ChannelScaling fromDataset(const TactileDataset& dataset);
  int channels() const noexcept { return static_cast<int>(scale.size()); }
  int constantChannels() const noexcept;
  // out[i] = in[i] * scale[i], i < channels()
  void apply(const double* in, float* out) const;
  // One sample's standardised error (the summand of the journal's Eq. 9):
  //   1/N' sum_i |a_i - b_i| / sigma_i  over the N' non-constant channels
  // (0 when every channel is constant).
  double meanStandardizedError(const double* a, const double* b) const;
};

}  // namespace onetip::haptics
