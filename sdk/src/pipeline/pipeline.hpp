// pipeline/pipeline.hpp — the threaded sensing pipeline: a capture thread
// reading a FrameSource and a processing thread running the FrameProcessor,
// joined by a bounded queue.
//
//   capture thread:    source.next() -> (pacing) -> frame queue (capacity N)
//       latest frame wins: when the queue is full the OLDEST waiting entry is
//       dropped and counted; with `lossless` the capture thread waits instead.
//       Reports of skipped frames and source errors always wait for room.
//   processing thread: frame -> FrameProcessor -> events (input_event.hpp)
//       -> callbacks (event callback per event, then the frame callback)
//       -> poll queues (bounded, oldest dropped and counted).
//
// Times: the arrival of a frame is the steady-clock instant it was handed to
// the frame queue (after the source returned it and after pacing); queue time
// is arrival to the start of processing; delivery is arrival to the end of the
// frame's callbacks. Stage times (ms) are kept over the last timing_window
// frames: capture (source.next()), queue, detect, track, triangulate, contact,
// pose, process (FrameProcessor, all stages), delivery.
//
// Source failures become error events (frame -1 for device errors), never
// exceptions: an error or skipped frame from the source; after
// max_consecutive_source_errors errors in a row the source is given up (an
// error event, then the pipeline finishes). A frame that cannot become the
// rest state (no reference yet, or after rereference()) gives an error event
// and the next good frame is tried.
//
// Stopping: stop() closes the queues, waits for the capture thread up to
// stop_timeout_ms (a source blocked inside next() is then abandoned: its
// thread owns the source and finishes on its own), and joins the processing
// thread after its current frame and callbacks.
//
// Thread-safety: start()/stop() from a controlling thread, never from a
// callback (PipelineStateError); everything else from any thread.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "capture/frame_source.hpp"
#include "input/input_event.hpp"
#include "pipeline/frame_processor.hpp"
#include "pipeline/timing_stats.hpp"

namespace onetip::pipeline {

using SteadyClock = std::chrono::steady_clock;

struct PipelineOptions {
  FrameProcessorOptions processor;
  int queue_capacity = 2;                 // 1..64 frames between the threads
  bool lossless = false;                  // capture waits for room instead of dropping the oldest frame
  double playback_rate = 0;               // > 0: pace frames at rate x their timestamps; 0: no pacing
  int event_queue_capacity = 1024;        // pollEvent() queue, 0..1000000 (0: off)
  int frame_queue_capacity = 4;           // pollFrame() queue, 0..1000 (0: off)
  int timing_window = 1000;               // 10..1000000 frames
  int max_consecutive_source_errors = 50; // 1..1000000
  int stop_timeout_ms = 2000;             // 10..600000
  void validate() const;                  // InputError naming the bad field
};

// An event with the frame it came from.
struct PipelineEvent {
  input::InputEvent event;
  std::int64_t frame = -1;            // source frame index, -1 for device-level errors
  SteadyClock::time_point arrival{};  // that frame's arrival (or the error's time)
};

// A frame's full result.
struct PipelineFrame {
  std::int64_t frame = -1;
  SteadyClock::time_point arrival{};
  double capture_ms = 0;  // source.next()
  double queue_ms = 0;    // arrival -> processing start
  FrameResult result;
};

struct PipelineStats {
  std::int64_t frames_captured = 0, frames_processed = 0, frames_dropped = 0, frames_skipped = 0,
               frames_lost = 0, source_errors = 0, events_emitted = 0, events_dropped = 0,
               frame_results_dropped = 0, callback_errors = 0;
  std::int64_t frames_unreadable = 0;  // of frames_skipped: skipped by the source (unreadable, malformed)
  bool source_abandoned = false;
  std::vector<StageSummary> stages;  // capture, queue, detect, track, triangulate, contact, pose, process, delivery
};

// start()/stop() called from inside a callback, or start() twice.
class PipelineStateError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

class Pipeline {
 public:
  using EventCallback = std::function<void(const PipelineEvent&)>;
  using FrameCallback = std::function<void(const PipelineFrame&)>;

  // Throws InputError for invalid options, calibration or pattern.
  Pipeline(std::unique_ptr<capture::FrameSource> source, const StereoCalibration& calib,
           const MarkerPattern& pattern, PipelineOptions options = {});
  ~Pipeline();  // stop()
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;

  // Before start(): `grey` becomes the rest state; InputError with the reason when it cannot.
  void setReference(const cv::Mat& grey);

  // Replaces the callback; waits for a call in progress unless called from that callback.
  void onEvent(EventCallback callback);
  void onFrame(FrameCallback callback);

  static constexpr double kNoTimeLimitS = 1e9;

  void start();
  void stop();
  bool running() const noexcept;
  bool finished() const noexcept;
  // Until the processing thread has ended (finished or stopped; stop() before start() ends a pipeline that
  // then never runs) or the timeout (< 0, infinite or >= kNoTimeLimitS: none; NaN: InputError); returns finished().
  bool waitFinished(double timeout_s) const;

  bool pollEvent(PipelineEvent& out);
  bool waitEvent(PipelineEvent& out, double timeout_s);
  bool pollFrame(PipelineFrame& out);

  void rezero() noexcept;
  void rereference() noexcept;
  PipelineStats stats() const;

 private:
  struct Shared;
  struct Processing;
  std::shared_ptr<Shared> shared_;
  std::unique_ptr<Processing> processing_;
};

}  // namespace onetip::pipeline
