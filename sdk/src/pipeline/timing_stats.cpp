#include "pipeline/timing_stats.hpp"

#include <algorithm>
#include <cmath>

namespace onetip::pipeline {

double percentile(std::vector<double>& samples, double p) {
  if (samples.empty()) return 0;
  const auto n = samples.size();
  const auto rank = std::clamp<std::size_t>(static_cast<std::size_t>(std::ceil(p * static_cast<double>(n))), 1, n);
  std::nth_element(samples.begin(), samples.begin() + static_cast<long>(rank - 1), samples.end());
  return samples[rank - 1];
}

double median(std::vector<double>& samples) {
  const auto n = samples.size();
  if (n == 0) return 0;
  std::nth_element(samples.begin(), samples.begin() + static_cast<long>(n / 2), samples.end());
  const double upper = samples[n / 2];
  if (n % 2 == 1) return upper;
  const double lower = *std::max_element(samples.begin(), samples.begin() + static_cast<long>(n / 2));
  return 0.5 * (lower + upper);
}

TimingStats::TimingStats(std::vector<std::string> stages, int window)
    : names_(std::move(stages)), window_(static_cast<std::size_t>(std::max(window, 1))), rings_(names_.size()) {}

void TimingStats::add(std::size_t index, double ms) {
  std::lock_guard lock(mutex_);
  Ring& r = rings_.at(index);
  if (r.samples.size() < window_) {
    r.samples.push_back(ms);
  } else {
    r.samples[r.next] = ms;
    r.next = (r.next + 1) % window_;
  }
}

std::vector<StageSummary> TimingStats::summary() const {
  std::vector<std::vector<double>> copies;
  {
    std::lock_guard lock(mutex_);
    for (const Ring& r : rings_) copies.push_back(r.samples);
  }
  std::vector<StageSummary> out;
  for (std::size_t i = 0; i < names_.size(); ++i) {
    std::vector<double>& s = copies[i];
    StageSummary sum;
    sum.stage = names_[i];
    sum.count = static_cast<std::int64_t>(s.size());
    if (!s.empty()) {
      sum.max_ms = *std::max_element(s.begin(), s.end());
      sum.p99_ms = percentile(s, 0.99);
      sum.median_ms = median(s);
    }
    out.push_back(sum);
  }
  return out;
}

}  // namespace onetip::pipeline
