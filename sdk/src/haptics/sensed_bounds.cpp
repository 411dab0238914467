#include "haptics/sensed_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/option_checks.hpp"

namespace onetip::haptics {

SensedBounds SensedBounds::fromDataset(const TactileDataset& dataset) {
  const auto n = static_cast<size_t>(std::max(dataset.channels, 0));
  std::vector<double> lo(n, std::numeric_limits<double>::infinity()), hi(n, -std::numeric_limits<double>::infinity());
  for (size_t r = 0; r < dataset.size(); ++r) {
    const float* s = dataset.sensedRow(r);
    for (size_t c = 0; c < n; ++c) {
      lo[c] = std::min(lo[c], static_cast<double>(s[c]));
      hi[c] = std::max(hi[c], static_cast<double>(s[c]));
    }
  }
  SensedBounds b;
  b.low_.resize(n);
  b.high_.resize(n);
  for (size_t c = 0; c < n; ++c) {
    if (!(lo[c] <= hi[c])) lo[c] = hi[c] = 0.0;  // no rows: only the magnitude rule applies
    const double span = hi[c] - lo[c];
    const double w = span > 0 ? span : std::max(1.0, std::abs(lo[c]));
    b.low_[c] = lo[c] - kSensedBoundSpans * w;
    b.high_[c] = hi[c] + kSensedBoundSpans * w;
  }
  return b;
}

std::string SensedBounds::refusal(std::span<const double> s) const {
  if (s.size() != low_.size())
    return "sensed vector of " + std::to_string(s.size()) + " channels, the dataset has " +
           std::to_string(low_.size());
  for (size_t c = 0; c < s.size(); ++c) {
    const std::string name = "sensed channel s" + std::to_string(c + 1);
    if (!std::isfinite(s[c])) return name + " is not finite (" + numberText(s[c]) + ")";
    if (s[c] < low_[c] || s[c] > high_[c])
      return name + " = " + numberText(s[c]) + " is outside " + rangeText(low_[c], high_[c]) +
             " (the dataset's range widened by ten times its span)";
  }
  return {};
}

}  // namespace onetip::haptics
