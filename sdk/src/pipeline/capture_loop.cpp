#include "pipeline/capture_loop.hpp"

#include <cmath>
#include <string>

namespace onetip::pipeline {

void Pipeline::Shared::requestStop() {
  {
    std::lock_guard lock(mutex);
    stop = true;
  }
  wake.notify_all();
  frames.close();
}

bool Pipeline::Shared::sleepUntil(SteadyClock::time_point when) {
  std::unique_lock lock(mutex);
  return !wake.wait_until(lock, when, [&] { return stop.load(); });
}

void Pipeline::Shared::captureLoop() {
  bool paced = false;
  SteadyClock::time_point pace_start{};
  double first_timestamp = 0;
  int consecutive_errors = 0;
  while (!stop) {
    const auto t0 = SteadyClock::now();
    capture::Frame f;
    bool threw = false;
    try {  // sources promise not to throw; one that does ends the stream as a failure, not the host
      f = source->next();
    } catch (const std::exception& e) {
      threw = true;
      f.status = capture::FrameStatus::error;
      f.message = std::string("the frame source failed: ") + e.what();
    }
    const auto t1 = SteadyClock::now();
    if (stop || f.status == capture::FrameStatus::end) break;
    Captured c;
    c.index = f.index;
    c.timestamp_s = f.timestamp_s;
    c.message = std::move(f.message);
    c.capture_ms = msBetween(t0, t1);
    if (f.status == capture::FrameStatus::error) {
      ++source_errors;
      c.kind = ++consecutive_errors >= options.max_consecutive_source_errors || threw ? Captured::Kind::source_failed
                                                                                       : Captured::Kind::source_error;
    } else {
      consecutive_errors = 0;
      if (f.status == capture::FrameStatus::skipped) {
        ++skipped;
        c.kind = Captured::Kind::skipped;
      } else {
        ++captured;
        c.grey = std::move(f.grey);
        timing.add(kCapture, c.capture_ms);
        if (options.playback_rate > 0) {
          if (!paced) {
            paced = true;
            pace_start = t1;
            first_timestamp = f.timestamp_s;
          }
          const double offset_s = (f.timestamp_s - first_timestamp) / options.playback_rate;
          if (std::isfinite(offset_s) && offset_s > 0 &&
              !sleepUntil(pace_start +
                          std::chrono::duration_cast<SteadyClock::duration>(std::chrono::duration<double>(offset_s))))
            break;
        }
      }
    }
    c.arrival = SteadyClock::now();
    const bool failed = c.kind == Captured::Kind::source_failed;
    // Only frames go stale: reports of skipped frames and source errors wait for room.
    const bool wait = options.lossless || c.kind != Captured::Kind::frame;
    if (frames.push(std::move(c), wait) == BoundedQueue<Captured>::PushResult::closed || failed) break;
  }
  frames.close();  // end of stream: the processing thread drains and finishes
  std::lock_guard lock(mutex);
  capture_exited = true;
  wake.notify_all();
}

}  // namespace onetip::pipeline
