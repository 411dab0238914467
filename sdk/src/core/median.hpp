// core/median.hpp — the median of a sample, as the robust statistics of the
// sensor's self-model, the view-shift test and the viewer's timing report take
// it: the sample of rank floor(n / 2) in ascending order (for an even n the
// upper of the two middle samples, not their mean, so the result is always
// one of the measured values); 0 for an empty sample. O(n) (nth_element).
#pragma once

#include <algorithm>
#include <vector>

namespace onetip {

inline double upperMedian(std::vector<double> v) {
  if (v.empty()) return 0;
  const auto mid = v.begin() + static_cast<long>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace onetip
