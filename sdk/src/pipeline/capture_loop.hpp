// pipeline/capture_loop.hpp — the capture side of Pipeline (private to the
// pipeline module): the stage names of its timing table, what the capture
// thread hands to the processing thread, and Pipeline::Shared, the state the
// capture thread touches. Shared is held by shared_ptr because the capture
// thread may outlive the Pipeline when a blocked read is abandoned at stop().
// Frames are paced to their timestamps when playback_rate > 0 (source time /
// playback_rate); times are wall-clock milliseconds (SteadyClock).
#pragma once

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <string>
#include <vector>

#include "pipeline/bounded_queue.hpp"
#include "pipeline/pipeline.hpp"

namespace onetip::pipeline {

enum Stage : std::size_t { kCapture, kQueue, kDetect, kTrack, kTriangulate, kContact, kPose, kProcess, kDelivery };
inline const std::vector<std::string> kStageNames{"capture", "queue", "detect",  "track",   "triangulate",
                                                  "contact", "pose",  "process", "delivery"};

inline double msBetween(SteadyClock::time_point a, SteadyClock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

// What the capture thread hands to the processing thread.
struct Captured {
  enum class Kind { frame, skipped, source_error, source_failed } kind = Kind::frame;
  cv::Mat grey;
  std::int64_t index = -1;
  double timestamp_s = 0;
  std::string message;
  SteadyClock::time_point arrival{};
  double capture_ms = 0;
};

// Everything the capture thread touches: it may outlive the Pipeline when a
// blocked read is abandoned at stop().
struct Pipeline::Shared {
  Shared(std::unique_ptr<capture::FrameSource> s, const PipelineOptions& o)
      : source(std::move(s)),
        options(o),
        frames(static_cast<std::size_t>(o.queue_capacity)),
        timing(kStageNames, o.timing_window) {}

  std::unique_ptr<capture::FrameSource> source;
  const PipelineOptions options;
  BoundedQueue<Captured> frames;
  TimingStats timing;
  std::atomic<bool> stop{false};
  std::mutex mutex;  // guards capture_exited; the pacing sleep waits on `wake`
  std::condition_variable wake;
  bool capture_exited = false;
  std::atomic<std::int64_t> captured{0}, skipped{0}, source_errors{0};

  void requestStop();
  // Sleeps until `when` or a stop request; false when stopping.
  bool sleepUntil(SteadyClock::time_point when);
  // The capture thread's body: reads the source, paces playback, hands frames on.
  void captureLoop();
};

}  // namespace onetip::pipeline
