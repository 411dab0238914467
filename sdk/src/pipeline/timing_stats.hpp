// pipeline/timing_stats.hpp — per-stage timing statistics over a sliding
// window of the most recent frames.
//
// For each named stage, the last `window` samples (milliseconds) are kept in
// a ring; summary() gives their count, median, 99th percentile and maximum.
// Percentiles are order statistics of the window (nearest rank:
// the ceil(p * n)-th smallest sample, so p99 of 100 samples is the 99th
// smallest), the median of an even count the mean of the two middle samples.
// Thread-safe: add() and summary() may be called concurrently.
#pragma once

#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace onetip::pipeline {

struct StageSummary {
  std::string stage;
  std::int64_t count = 0;  // samples in the window
  double median_ms = 0, p99_ms = 0, max_ms = 0;
};

// Nearest-rank percentile (p in [0, 1]) and median of `samples` (reordered); 0 when empty.
double percentile(std::vector<double>& samples, double p);
double median(std::vector<double>& samples);

class TimingStats {
 public:
  // `stages`: the stage names, in the order summary() reports them; window >= 1.
  TimingStats(std::vector<std::string> stages, int window);
  // Adds one sample (ms) to stage `index` (the position in `stages`).
  void add(std::size_t index, double ms);
  std::vector<StageSummary> summary() const;

 private:
  struct Ring {
    std::vector<double> samples;
    std::size_t next = 0;
  };
  std::vector<std::string> names_;
  std::size_t window_;
  mutable std::mutex mutex_;
  std::vector<Ring> rings_;
};

}  // namespace onetip::pipeline
