/**
 * @file onetip/sensor.hpp
 * @brief The fingertip sensor: a frame source, its calibration and pattern, and
 * the threaded pipeline that turns frames into 6-D input (onetip::Sensor).
 *
 *     source thread:     frames from the source (camera, folder, video, simulator)
 *       -> bounded queue (latest frame wins unless SensorOptions::lossless)
 *     processing thread: detect, track, triangulate, contact, pose -> events
 *       -> your callbacks (on the processing thread), then the poll queues
 *
 * Positions in mm in the sensor frame S, angles in degrees, times in seconds
 * (events.hpp, types.hpp). The first good frame (or the reference image, when
 * given) is the rest state: the finger must not touch the pad then.
 *
 * Thread rules, call by call:
 *   - constructor, destructor: one thread; the destructor calls stop(). Never
 *     destroy a Sensor from inside one of its own callbacks.
 *   - start(), stop(): from any thread except inside a callback of this sensor
 *     (Error of kind ErrorKind::state there), not concurrently with each other.
 *   - onEvent(), onFrame(): any thread, any time (also while running). Callbacks
 *     run on the processing thread, one at a time, in frame order; keep them
 *     short (they delay the next frame). A callback that throws is caught,
 *     counted (SensorStats::callback_errors) and reported as an error event in
 *     the poll queue; the sensor goes on.
 *   - pollEvent(), waitEvent(), pollFrame(), stats(), reZero(), reReference(),
 *     running(), finished(), waitFinished(), source(): any thread, also
 *     concurrently and from inside callbacks (waitEvent() or waitFinished()
 *     inside a callback would wait for the thread that runs it: don't).
 */
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

/// What a Sensor opens: the frame source and the files that describe the rig. The file formats are in docs/reference.md.
struct SensorConfig {
  /// An empty configuration; set at least `source` before use.
  SensorConfig() = default;
  /**
   * @brief A configuration from its four strings.
   * @param source_ the frame source (see #source).
   * @param calibration_ the calibration file, or empty (see #calibration).
   * @param pattern_ the pattern file, or empty (see #pattern).
   * @param reference_ the rest-state image, or empty (see #reference).
   */
  explicit SensorConfig(std::string source_, std::string calibration_ = {}, std::string pattern_ = {},
               std::string reference_ = {})
      : source(std::move(source_)), calibration(std::move(calibration_)), pattern(std::move(pattern_)),
        reference(std::move(reference_)) {}

  /// The frame source: "v4l2:/dev/videoN" (a V4L2 camera), a folder of image
  /// files (sorted by name), a recorded session folder (holding session.csv),
  /// a video file, or "sim:SCENARIO.yaml" (the simulator as a camera).
  std::string source;
  /// The stereo calibration file (OpenCV FileStorage YAML: image size, split,
  /// flips, intrinsics, R and T in mm). For "sim:" sources it and #pattern may
  /// both be left empty: the simulator's own exact calibration and pattern are
  /// used then (what SimulatedSensor::saveCalibration() writes). Other sources need both.
  std::string calibration;
  /// The marker pattern file (rows, cols, square_mm). Given together with #calibration, or neither.
  std::string pattern;
  /// Optional rest-state image (8-bit grey or colour, converted to grey), of
  /// the calibration's image size, with no finger on the pad; empty: the first
  /// good frame of the source is the rest state.
  std::string reference;
};

/// Timing of one stage: median, 99th percentile and maximum over the last SensorOptions::timing_window frames.
struct TimingSummary {
  /// "capture", "queue", "detect", "track", "triangulate", "contact", "pose",
  /// "process" (as in StageTimes), or "delivery" (frame arrival to the end of its callbacks).
  std::string stage;
  std::int64_t count = 0;  ///< Samples in the window (at most SensorOptions::timing_window).
  double median_ms = 0, p99_ms = 0, max_ms = 0;
  /// @var median_ms
  /// @brief Median of the window, ms (0 when empty).
  /// @var p99_ms
  /// @brief 99th percentile of the window (nearest rank), ms.
  /// @var max_ms
  /// @brief Largest sample of the window, ms.
};

/// Counters of a Sensor since it was created (Sensor::stats()).
struct SensorStats {
  std::int64_t frames_captured = 0;   ///< Good frames from the source.
  std::int64_t frames_processed = 0;  ///< Frames through the processor (any status).
  std::int64_t frames_dropped = 0;    ///< Stale frames dropped by the latest-frame-wins queue (never with SensorOptions::lossless).
  std::int64_t frames_skipped = 0;    ///< Unusable frames (from the source or the processor).
  std::int64_t frames_lost = 0;       ///< Frames with too few markers (FrameStatus::lost).
  std::int64_t source_errors = 0;     ///< Device-level errors of the source.
  std::int64_t events_emitted = 0;    ///< Events produced (to callbacks and the poll queue).
  std::int64_t events_dropped = 0;    ///< Events dropped from a full poll queue (SensorOptions::event_queue_capacity).
  std::int64_t frame_results_dropped = 0;  ///< Results dropped from a full pollFrame() queue (SensorOptions::frame_queue_capacity).
  std::int64_t callback_errors = 0;   ///< Callbacks that threw.
  bool source_abandoned = false;      ///< stop() gave up waiting for a blocked source read (SensorOptions::stop_timeout_ms).
  std::vector<TimingSummary> stages;  ///< One entry per stage, in the order listed in TimingSummary::stage.
};

/**
 * @brief The fingertip sensor: opens a frame source and runs the pipeline that
 * turns its frames into 6-D input events.
 *
 * Typical use: construct, set callbacks (onEvent(), onFrame()) or poll
 * (pollEvent(), waitEvent()), start(), and stop() or destroy when done. A
 * Sensor runs once. See the file's description for the thread rules; every
 * member that fails throws onetip::Error.
 */
class ONETIP_EXPORT Sensor {
 public:
  /// Called with each event, on the processing thread; the reference is valid during the call only.
  using EventCallback = std::function<void(const Event&)>;
  /// Called with each frame's result after its events, on the processing thread; the reference is valid during the call only.
  using FrameCallback = std::function<void(const FrameResult&)>;

  /**
   * @brief Opens the source and reads the calibration, pattern and reference
   * image; does not start capturing. No thread is started yet.
   * @param config what to open (SensorConfig).
   * @param options how to run; checked as SensorOptions::validate() does.
   * @throws onetip::Error of kind ErrorKind::input naming the bad file, source
   *         or option: an empty or unopenable source, a missing or malformed
   *         calibration or pattern file, only one of the two given, neither
   *         given for a source other than "sim:", a reference image that cannot
   *         be read, has the wrong size or cannot become the rest state, an
   *         option out of its range.
   */
  explicit Sensor(const SensorConfig& config, const SensorOptions& options = {});
  /// Stops the sensor (as stop(), errors ignored) and frees it. Not from inside one of its own callbacks, nor while another thread still uses it.
  ~Sensor();
  Sensor(const Sensor&) = delete;             ///< Not copyable.
  Sensor& operator=(const Sensor&) = delete;  ///< Not copyable.

  /**
   * @brief Starts the capture and processing threads; returns at once.
   *
   * Any thread but the sensor's own callbacks; not concurrently with stop().
   * @throws onetip::Error of kind ErrorKind::state when called a second time
   *         (also after stop(): a sensor runs once) or from inside a callback
   *         of this sensor.
   */
  void start();
  /**
   * @brief Stops both threads and returns once the callbacks have finished.
   *
   * A source blocked inside a read is abandoned after
   * SensorOptions::stop_timeout_ms (SensorStats::source_abandoned; its thread
   * ends on its own later). Idempotent. Before start() it ends a sensor that
   * never ran: waitFinished() returns (false) in every thread, and start()
   * then throws. Events and results already queued stay pollable. Any thread but the sensor's own
   * callbacks; not concurrently with start().
   * @throws onetip::Error of kind ErrorKind::state when called from inside a
   *         callback of this sensor (it would wait for itself).
   */
  void stop();
  /// @return true when started and not yet stopped or finished. Any thread; never throws.
  bool running() const noexcept;
  /// @return true once the source ended (or was given up after errors) and every frame was processed; false after stop() ended the run early. Any thread; never throws.
  bool finished() const noexcept;
  /**
   * @brief Waits until the processing thread has ended (the source finished,
   * or stop()) or the timeout expires. Any thread; not from inside a callback
   * of this sensor (it would wait for the thread that runs it).
   * @param timeout_s the longest wait, seconds; negative, infinite or
   *        >= 1e9: no limit. Before start() it waits for another thread to
   *        start the sensor and the run to end, or to stop() it (also as the
   *        destructor or onetip_sensor_destroy does).
   * @throws onetip::Error of kind ErrorKind::input when timeout_s is NaN.
   * @return finished().
   */
  bool waitFinished(double timeout_s = -1) const;

  /**
   * @brief Sets the event callback, replacing the previous one; an empty
   * function removes it.
   *
   * The callback is copied; what it captures must stay valid until it is
   * replaced or the sensor is destroyed. Called from another thread, this
   * waits for a call in progress to finish, so the old callback is never
   * called after it returns; called from inside a callback, the new one takes
   * effect from the next frame. Any thread, any time (also while running).
   * @param callback called once per event, on the processing thread, one call at a time, in frame order.
   */
  void onEvent(EventCallback callback);
  /**
   * @brief Sets the frame callback, replacing the previous one; an empty
   * function removes it. Same rules as onEvent().
   * @param callback called once per processed frame, after that frame's event
   *        callbacks, on the processing thread.
   */
  void onFrame(FrameCallback callback);

  /**
   * @brief Takes the oldest queued event, without blocking.
   *
   * The poll queue receives every event (after the callbacks ran), plus an
   * error event for each callback that threw; it holds up to
   * SensorOptions::event_queue_capacity events (0: no queue, always false),
   * the oldest dropped when full (SensorStats::events_dropped). Any thread,
   * also concurrently and from inside callbacks.
   * @param event filled when an event was queued; untouched otherwise.
   * @return true when an event was taken.
   */
  bool pollEvent(Event& event);
  /**
   * @brief Takes the oldest queued frame result, without blocking.
   *
   * Holds up to SensorOptions::frame_queue_capacity results (0: no queue,
   * always false), the oldest dropped when full (SensorStats::frame_results_dropped).
   * Any thread, also concurrently and from inside callbacks.
   * @param frame filled when a result was queued; untouched otherwise.
   * @return true when a result was taken.
   */
  bool pollFrame(FrameResult& frame);
  /**
   * @brief Waits up to timeout_s seconds for an event (see pollEvent()).
   *
   * Any thread; not from inside a callback of this sensor (the event it waits
   * for would come from the thread it blocks).
   * @param event filled when an event was taken; untouched otherwise.
   * @param timeout_s the longest wait, seconds; negative, NaN or infinite: no
   *        wait at all (as pollEvent()). Before start() it does not wait.
   * @return true when an event was taken; false on time-out, or at once when
   *         the sensor has finished or stopped and the queue is empty.
   */
  bool waitEvent(Event& event, double timeout_s);

  /// Re-zero: the 6-D input restarts from zero at the next processed frame (as if a new contact began there). Any thread, also from callbacks; never throws.
  void reZero();
  /// Re-reference: the next good frame becomes the new rest state (the finger must be off the pad) and S is re-derived from it; a frame that cannot (too few markers) gives an error event and the next is tried. Any thread, also from callbacks; never throws.
  void reReference();

  /// @return a snapshot of the counters and the per-stage timing. Any thread.
  SensorStats stats() const;
  /// @return the source string the sensor was opened with; the reference is valid as long as the Sensor. Never throws.
  const std::string& source() const noexcept;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace onetip
