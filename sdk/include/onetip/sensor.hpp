// onetip/sensor.hpp — the fingertip sensor: a frame source, its calibration
// and pattern, and the threaded pipeline that turns frames into 6-D input.
//
//   source thread:   frames from the source (camera, folder, video, simulator)
//     -> bounded queue (latest frame wins unless options.lossless; SensorOptions)
//   processing thread: detect, track, triangulate, contact, pose -> events
//     -> your callbacks (on the processing thread), then the poll queues
//
// Positions in mm in the sensor frame S, angles in degrees, times in seconds
// (events.hpp). The first frame (or the reference image, when given) is the
// rest state: the finger must not touch the pad then.
//
// Thread-safety, call by call:
//   - constructor, destructor: one thread; the destructor calls stop().
//   - start(), stop(): from any thread except inside a callback (Error kind
//     state there), not concurrently with each other.
//   - onEvent(), onFrame(): any thread, any time (also while running; a
//     callback being replaced finishes its current call first). Callbacks run
//     on the processing thread, one at a time, in frame order; keep them short
//     (they delay the next frame). A callback that throws is caught, counted
//     (SensorStats::callback_errors) and reported as an error event in the
//     poll queue; the sensor goes on.
//   - pollEvent(), waitEvent(), pollFrame(), stats(), reZero(), reReference(),
//     running(), finished(), waitFinished(), source(): any thread, also
//     concurrently and from inside callbacks (waitEvent()/waitFinished() inside
//     a callback would wait for themselves: don't).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "onetip/error.hpp"
#include "onetip/events.hpp"
#include "onetip/export.hpp"
#include "onetip/sensor_options.hpp"

namespace onetip {

// What to open. Paths are files of docs/reference.md (calibration, pattern).
struct SensorConfig {
  SensorConfig() = default;
  explicit SensorConfig(std::string source_, std::string calibration_ = {}, std::string pattern_ = {},
               std::string reference_ = {})
      : source(std::move(source_)), calibration(std::move(calibration_)), pattern(std::move(pattern_)),
        reference(std::move(reference_)) {}

  // "v4l2:/dev/videoN", a folder of image files (sorted by name), a video
  // file, or "sim:SCENARIO.yaml" (the simulator as a camera).
  std::string source;
  // Calibration and pattern files. For "sim:" sources both may be left empty:
  // the simulator's own exact calibration and pattern are used then (what
  // SimulatedSensor::saveCalibration() writes). Other sources need both.
  std::string calibration;
  std::string pattern;
  // Optional rest-state image (8-bit grey or colour, converted to grey);
  // empty: the first good frame of the source is the rest state.
  std::string reference;
};

// Median, 99th percentile and maximum over the last options.timing_window frames.
struct TimingSummary {
  std::string stage;  // "capture", "queue", "detect", "track", "triangulate", "contact", "pose", "process",
                      // "delivery" (frame arrival to the end of its callbacks)
  std::int64_t count = 0;
  double median_ms = 0, p99_ms = 0, max_ms = 0;
};

struct SensorStats {
  std::int64_t frames_captured = 0;   // good frames from the source
  std::int64_t frames_processed = 0;  // frames through the processor (any status)
  std::int64_t frames_dropped = 0;    // stale frames dropped by the latest-frame-wins queue
  std::int64_t frames_skipped = 0;    // unusable frames (from the source or the processor)
  std::int64_t frames_lost = 0;       // too few markers
  std::int64_t source_errors = 0;     // device-level errors of the source
  std::int64_t events_emitted = 0;    // events produced (callbacks and poll queue)
  std::int64_t events_dropped = 0;    // events dropped from a full poll queue
  std::int64_t frame_results_dropped = 0;  // results dropped from a full pollFrame() queue
  std::int64_t callback_errors = 0;   // callbacks that threw
  bool source_abandoned = false;      // stop() gave up waiting for a blocked source read
  std::vector<TimingSummary> stages;  // in the order listed in TimingSummary::stage
};

class ONETIP_EXPORT Sensor {
 public:
  using EventCallback = std::function<void(const Event&)>;
  using FrameCallback = std::function<void(const FrameResult&)>;

  // Opens the source and reads the calibration, pattern and reference; does
  // not start capturing. Throws Error(input) naming the bad file, source or
  // option.
  explicit Sensor(const SensorConfig& config, const SensorOptions& options = {});
  ~Sensor();
  Sensor(const Sensor&) = delete;
  Sensor& operator=(const Sensor&) = delete;

  // Starts the capture and processing threads. A sensor runs once: start()
  // after stop() or a second start() throws Error(state).
  void start();
  // Stops both threads and returns once callbacks have finished (a source
  // blocked inside a read is abandoned after options.stop_timeout_ms).
  // Idempotent; events already queued stay pollable.
  void stop();
  bool running() const noexcept;   // started and not yet stopped or finished
  bool finished() const noexcept;  // the source ended (or failed) and every frame was processed
  // Waits until finished() or the timeout (seconds; < 0: no limit); returns finished().
  bool waitFinished(double timeout_s = -1) const;

  void onEvent(EventCallback callback);  // empty: none
  void onFrame(FrameCallback callback);  // empty: none

  // Non-blocking: the oldest queued event or frame result, false when none.
  bool pollEvent(Event& event);
  bool pollFrame(FrameResult& frame);
  // Blocks up to timeout_s seconds for an event; false on time-out or once
  // the sensor has finished or stopped and the queue is empty.
  bool waitEvent(Event& event, double timeout_s);

  // Re-zero: the 6-D input restarts from zero at the next frame (as if a new
  // contact began there).
  void reZero();
  // Re-reference: the next good frame becomes the new rest state (the finger
  // must be off the pad); S is re-derived from it.
  void reReference();

  SensorStats stats() const;
  const std::string& source() const noexcept;  // the source string it was opened with

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace onetip
