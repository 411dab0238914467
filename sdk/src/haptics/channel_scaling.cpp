#include "haptics/channel_scaling.hpp"

#include <algorithm>
#include <cmath>

namespace onetip::haptics {

ChannelScaling ChannelScaling::fromDataset(const TactileDataset& dataset) {
  const auto n = static_cast<size_t>(dataset.channels);
  std::vector<double> mean(n, 0.0), m2(n, 0.0);
  // Welford's update: stable for large, offset channels (12-bit counts near 2000).
  for (size_t r = 0; r < dataset.size(); ++r) {
    const float* s = dataset.sensedRow(r);
    const double k = static_cast<double>(r + 1);
    for (size_t c = 0; c < n; ++c) {
      const double delta = s[c] - mean[c];
      mean[c] += delta / k;
      m2[c] += delta * (s[c] - mean[c]);
    }
  }
  ChannelScaling out;
  out.sigma.resize(n);
  out.scale.resize(n);
  const double rows = static_cast<double>(std::max<size_t>(dataset.size(), 1));
  for (size_t c = 0; c < n; ++c) {
    out.sigma[c] = std::sqrt(m2[c] / rows);
    const bool constant = out.sigma[c] <= 1e-9 * std::max(1.0, std::abs(mean[c]));
    out.scale[c] = constant ? 0.0 : 1.0 / out.sigma[c];
  }
  return out;
}

int ChannelScaling::constantChannels() const noexcept {
  return static_cast<int>(std::count(scale.begin(), scale.end(), 0.0));
}

void ChannelScaling::apply(const double* in, float* out) const {
  for (size_t c = 0; c < scale.size(); ++c) out[c] = static_cast<float>(in[c] * scale[c]);
}

double ChannelScaling::meanStandardizedError(const double* a, const double* b) const {
  const int counted = channels() - constantChannels();
  if (counted == 0) return 0.0;
  double sum = 0.0;
  for (size_t c = 0; c < scale.size(); ++c) sum += std::abs(a[c] - b[c]) * scale[c];
  return sum / counted;
}

}  // namespace onetip::haptics
