/**
 * @file onetip/sensor_option_table.hpp
 * @brief The table of SensorOptions: one row per option, the only place an
 * option is declared.
 *
 * Every surface derives from it or is checked against it by tests (label
 * `options`): the C++ struct and its validate(), the options file's keys,
 * reader, writer and messages, the conversion to the pipeline's settings, the
 * C ABI's introspection and keyed accessors, Python's SensorOptions attributes
 * and C#'s option table. The reference documents each row as a field of
 * onetip::SensorOptions.
 *
 * No include guard on purpose: an X-macro list. Define
 *     ONETIP_OPTION(name, Type, min, max, unit, doc, default...)
 * and include this file to expand one row per option, in this order (the
 * order of the options file and of SensorOptions::table()):
 *   - name: the C++ field, the file key, the Python attribute and the C key;
 *   - Type: int, double, bool, FilterKind or AxisArray (six values in Input6
 *     order [dx, dy, dz, yaw, pitch, roll]); it gives the OptionType;
 *   - min, max: the closed range of every value (bool 0..1, FilterKind 0..2);
 *   - unit: "" for counts and plain factors; "mm|deg" on an axis array means
 *     mm for dx, dy, dz and degrees for yaw, pitch, roll;
 *   - doc: one line for generated help and bindings;
 *   - default: the initialiser (six numbers for an AxisArray).
 *
 * Checks that involve two options (release_mm < press_mm) live in
 * sdk/src/core/option_table.cpp, beside the code that derives validate().
 *
 * Adding an option: one row here, then its consumer code: the pipeline
 * setting it feeds (one line of forEachPipelineField in
 * sdk/src/pipeline/options_io.cpp) and, since the C struct onetip_options is
 * fixed-layout, a field there, a line of forEachCField
 * (bindings/c/src/c_options.cpp) and the C# mirror
 * (bindings/csharp/src/SensorOptions.cs; a new C field is an incompatible
 * change of the C ABI), and its row in docs/reference.md. The `options` tests
 * fail until every surface carries it.
 */
#ifndef ONETIP_OPTION
#error "define ONETIP_OPTION(name, Type, min, max, unit, doc, default...) before including this file"
#endif

// --- threads and queues ---
ONETIP_OPTION(queue_capacity, int, 1, 64, "frames", "frames waiting between the capture and the processing thread", 2)
// false (default, live cameras): the latest frame wins; when the queue is full
// the OLDEST waiting frame is dropped and counted (SensorStats::frames_dropped).
// true: capture waits for room (nothing dropped; files, "sim:" sources, tests).
ONETIP_OPTION(lossless, bool, 0, 1, "", "true: capture waits for room instead of dropping the oldest frame", false)
// File and "sim:" sources: 0 plays them as fast as they decode; r > 0 paces
// them at r times their own timestamps (1 = real time). Ignored for cameras.
ONETIP_OPTION(playback_rate, double, 0, 1e6, "", "file and sim: sources: 0 as fast as they decode, 1 real time", 0)
// When a queue is full its oldest entry is dropped and counted; 0 turns it off.
ONETIP_OPTION(event_queue_capacity, int, 0, 1000000, "events", "pollEvent()/waitEvent() queue length, 0: off", 1024)
ONETIP_OPTION(frame_queue_capacity, int, 0, 1000, "frames", "pollFrame() queue length, 0: off", 4)
ONETIP_OPTION(timing_window, int, 10, 1000000, "frames", "most recent frames in the per-stage timing statistics", 1000)
ONETIP_OPTION(max_consecutive_source_errors, int, 1, 1000000, "errors",
              "errors in a row after which the source is given up (an error event, then the end)", 50)
// stop() abandons a read that blocks longer (the thread finishes on its own later).
ONETIP_OPTION(stop_timeout_ms, int, 10, 600000, "ms", "how long stop() waits for a source blocked in a read", 2000)

// --- processing ---
ONETIP_OPTION(min_markers, int, 3, 1000000, "markers", "fewer triangulated markers: the frame is lost", 12)
// The paper's working range: |dx|, |dy| <= 4 mm, dz <= 3 mm, |yaw| <= 15 deg,
// |pitch|, |roll| <= 40 deg. Beyond it a frame is out_of_range and raw is
// clamped to clamp_factor times it.
ONETIP_OPTION(working_range, AxisArray, 0.001, 1000, "mm|deg", "working range per axis; beyond it out_of_range",
              4, 4, 3, 15, 40, 40)
ONETIP_OPTION(clamp_factor, double, 1, 100, "", "raw is clamped to this many working ranges", 1.5)
// The press button: down when dz > press_mm, up again when dz < release_mm (< press_mm).
ONETIP_OPTION(press_mm, double, 0.001, 100, "mm", "the press button goes down when dz exceeds this", 1.5)
ONETIP_OPTION(release_mm, double, -100, 100, "mm", "the press button goes up when dz falls below this", 1.0)
// Interaction shaping of `input` (not `raw`): y = gain * sign(x) * max(0, |x| - dead_zone).
ONETIP_OPTION(gain, AxisArray, -1000, 1000, "", "per axis, input = gain * sign(x) * max(0, abs(x) - dead_zone)",
              1, 1, 1, 1, 1, 1)
ONETIP_OPTION(dead_zone, AxisArray, 0, 1000, "mm|deg", "per axis, magnitudes below it give 0", 0, 0, 0, 0, 0, 0)
ONETIP_OPTION(filter, FilterKind, 0, 2, "", "smoothing of input: none, moving_average or one_euro", FilterKind::none)
ONETIP_OPTION(filter_window, int, 1, 10000, "frames", "moving_average: frames averaged", 5)
// The 1-euro filter (Casiez et al. 2012): cutoff = min_cutoff + beta * |d input / dt|.
ONETIP_OPTION(filter_min_cutoff_hz, double, 0.001, 1000, "Hz", "one_euro: cutoff at rest", 1.0)
ONETIP_OPTION(filter_beta, double, 0, 1000, "", "one_euro: cutoff increase per unit of speed", 0.05)
ONETIP_OPTION(filter_derivative_cutoff_hz, double, 0.001, 1000, "Hz", "one_euro: cutoff of the speed estimate", 1.0)
