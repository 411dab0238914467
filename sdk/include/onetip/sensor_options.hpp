// onetip/sensor_options.hpp — how a Sensor runs: its threads and queues, and
// the processing settings an application may tune. Plain values with
// defaults; validate() names the first bad field; load() reads plain YAML or
// JSON (errors name the file, line and key), save() writes YAML.
//
// Axis arrays are in Input6 order [dx, dy, dz, yaw, pitch, roll]: mm for the
// first three, degrees for the rest (docs/reference.md).
//
// File format (every key optional; a missing key keeps its default, an
// unknown key is an error so typos do not pass silently):
//   queue_capacity: 2            lossless: 0            playback_rate: 0
//   event_queue_capacity: 1024   frame_queue_capacity: 4
//   timing_window: 1000          max_consecutive_source_errors: 50
//   stop_timeout_ms: 2000        min_markers: 12
//   working_range: [4, 4, 3, 15, 40, 40]   clamp_factor: 1.5
//   press_mm: 1.5                release_mm: 1.0
//   gain: [1, 1, 1, 1, 1, 1]     dead_zone: [0, 0, 0, 0, 0, 0]
//   filter: "none"               # "none", "moving_average" or "one_euro"
//   filter_window: 5  filter_min_cutoff_hz: 1.0  filter_beta: 0.05  filter_derivative_cutoff_hz: 1.0
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "onetip/export.hpp"

namespace onetip {

enum class FilterKind : std::uint8_t {
  none = 0,            // no smoothing
  moving_average = 1,  // the mean of the last filter_window frames (the paper's filter)
  one_euro = 2,        // the 1-euro filter (Casiez et al. 2012): little lag while moving
};

struct ONETIP_EXPORT SensorOptions {
  // --- threads and queues ---
  // Frames waiting between the capture and the processing thread, 1..64.
  int queue_capacity = 2;
  // false (default, live cameras): the latest frame wins; when the queue is
  // full the OLDEST waiting frame is dropped and counted (SensorStats::frames_dropped).
  // true: capture waits for room instead (nothing dropped; for files, "sim:"
  // sources and tests that need every frame).
  bool lossless = false;
  // File and "sim:" sources: 0 plays them as fast as they decode; r > 0 paces
  // them at r times their own timestamps (1 = real time). Ignored for cameras.
  double playback_rate = 0;
  // pollEvent()/waitEvent() queue length (0: off, for callback-only users);
  // when full the oldest event is dropped and counted. 0..1000000.
  int event_queue_capacity = 1024;
  // pollFrame() queue length (0: off); the oldest result is dropped when full. 0..1000.
  int frame_queue_capacity = 4;
  // Frames in the per-stage timing statistics (the most recent ones), 10..1000000.
  int timing_window = 1000;
  // The source is given up (an error event, then the sensor finishes) after
  // this many errors in a row, 1..1000000.
  int max_consecutive_source_errors = 50;
  // stop() waits this long for a source that blocks inside a read before it
  // abandons that read (the thread finishes on its own later), 10..600000 ms.
  int stop_timeout_ms = 2000;

  // --- processing ---
  int min_markers = 12;  // fewer triangulated markers: the frame is lost (no pose update), >= 3
  // The working range: |dx|, |dy| <= 4 mm, dz <= 3 mm, |yaw| <= 15 deg, |pitch|, |roll| <= 40 deg
  // (the paper's). Beyond it a frame is out_of_range and raw is clamped to
  // clamp_factor times it. All > 0.
  std::array<double, 6> working_range{4, 4, 3, 15, 40, 40};
  double clamp_factor = 1.5;  // >= 1
  // The press button: down when dz > press_mm, up again when dz < release_mm (< press_mm).
  double press_mm = 1.5;
  double release_mm = 1.0;
  // Interaction shaping of `input` (not `raw`): y = gain * sign(x) * max(0, |x| - dead_zone).
  std::array<double, 6> gain{1, 1, 1, 1, 1, 1};
  std::array<double, 6> dead_zone{0, 0, 0, 0, 0, 0};
  FilterKind filter = FilterKind::none;
  int filter_window = 5;                    // moving_average, frames >= 1
  double filter_min_cutoff_hz = 1.0;        // one_euro, > 0
  double filter_beta = 0.05;                // one_euro, >= 0
  double filter_derivative_cutoff_hz = 1.0; // one_euro, > 0

  // Throws Error(ErrorKind::input) naming the first bad field.
  void validate() const;
  // Reads a file written by save() or by hand (format above); throws
  // Error(ErrorKind::input) naming the file and the key when it cannot.
  static SensorOptions load(const std::string& path);
  // Writes every field; the file is replaced atomically (never half-written).
  void save(const std::string& path) const;
};

}  // namespace onetip
