// haptics/sensed_bounds.hpp — which sensed vectors a dataset can answer: the
// check a live sensed vector passes before it is rendered and drives a device.
//
// A vector is refused when its length is not the dataset's channel count, when
// any value is not finite (NaN, +-Inf), or when a value lies outside
//
//   [min_i - K w_i, max_i + K w_i],   K = kSensedBoundSpans = 10,
//   w_i = max_i - min_i                (the channel's recorded span), or
//   w_i = max(1, |min_i|)              for a channel that never varied,
//
// min_i and max_i being channel i's extremes over the dataset's rows, in the
// sensor's own units. The renderer answers any query with the nearest rows, so
// a reading far outside every recorded one would still be rendered as the
// nearest edge of the dataset: a sensor in no state the display ever produced,
// a unit mistake, or a corrupted sample (1e308, which becomes +Inf in the
// renderer's float search space). Ten spans beyond the extremes leaves room for
// contacts the display cannot reproduce (harder, wider) and refuses what no
// reading of the recorded sensor can mean. A constant channel carries no
// distance information (channel_scaling.hpp gives it scale 0), so it is bounded
// only by its value's order of magnitude.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "haptics/tactile_dataset.hpp"

namespace onetip::haptics {

constexpr double kSensedBoundSpans = 10.0;

class SensedBounds {
 public:
  static SensedBounds fromDataset(const TactileDataset& dataset);

  // Empty when s can be rendered; otherwise one line naming the first bad
  // channel (1-based, as the dataset's s1..sN columns), its value and bound.
  std::string refusal(std::span<const double> s) const;
  int channels() const noexcept { return static_cast<int>(low_.size()); }
  double low(int channel) const { return low_.at(static_cast<size_t>(channel)); }
  double high(int channel) const { return high_.at(static_cast<size_t>(channel)); }

 private:
  std::vector<double> low_, high_;  // per channel, sensor units
};

}  // namespace onetip::haptics
