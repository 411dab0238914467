/**
 * @file onetip/events.hpp
 * @brief What a running Sensor reports: discrete events (Event) and per-frame
 * results (FrameResult), and the clock they are stamped with.
 *
 * Frames and units (docs/reference.md): positions in millimetres in the sensor
 * frame S (origin at the rest-state marker centroid, z out of the pad towards
 * the finger, x along increasing marker column, y = z × x); angles in degrees;
 * Input6 = [dx, dy, dz, yaw, pitch, roll], the finger's motion since contact
 * onset (types.hpp).
 *
 * Times, in seconds: `t` is the frame's own timestamp from its source (the
 * driver's capture time for V4L2 cameras, the scenario time for "sim:"
 * sources, the recorded time for session folders, the container's position
 * for video files, frame index / 30 for a plain folder of images); `arrival_s`
 * is when the frame arrived from the source, on the steady clock of
 * onetip::clockSeconds(), so `clockSeconds() - arrival_s` in a callback is the
 * latency of that event.
 *
 * Events and results are plain values handed out by copy (Sensor::pollEvent(),
 * Sensor::pollFrame()) or by const reference to a callback, valid for the
 * duration of that call; copy what you keep.
 */
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "onetip/export.hpp"
#include "onetip/types.hpp"

namespace onetip {

/**
 * @brief Seconds on the monotonic clock (std::chrono::steady_clock) shared by
 * the library and its callers: the clock of Event::arrival_s and
 * FrameResult::arrival_s.
 *
 * Its origin is unspecified (not wall-clock time): use only differences.
 * Any thread; never throws.
 * @return the current time of that clock, s.
 */
ONETIP_EXPORT double clockSeconds() noexcept;

/// The kind of an Event.
enum class EventType : std::uint8_t {
  /// A contact starts; the 6-D input restarts from zero.
  contact_begin = 0,
  /// The contact ended; the 6-D input returns to zero. When its finger lifts
  /// while another stays on the pad, contact_begin for that one follows in the same frame.
  contact_end = 1,
  input = 2,          ///< The 6-D input of a frame in contact (one per such frame).
  press = 3,          ///< The press button went down (dz rose above SensorOptions::press_mm).
  release = 4,        ///< The press button went up (dz fell below SensorOptions::release_mm).
  state_changed = 5,  ///< The contact state (none/stick/partial_slip/slip) differs from the previous frame's.
  /// Something the caller should know: a source error, a frame that could not
  /// be used, too few markers, a callback that threw; Event::message says what.
  error = 6,
};

/**
 * @brief The event type's name.
 * @param e an event type; a value outside the enumerators gives "error".
 * @return "contact_begin", "contact_end", "input", "press", "release",
 *         "state_changed" or "error" (a static string).
 */
constexpr std::string_view toString(EventType e) noexcept {
  switch (e) {
    case EventType::contact_begin: return "contact_begin";
    case EventType::contact_end: return "contact_end";
    case EventType::input: return "input";
    case EventType::press: return "press";
    case EventType::release: return "release";
    case EventType::state_changed: return "state_changed";
    case EventType::error: break;
  }
  return "error";
}

/// One event of a running Sensor (see EventType).
struct Event {
  EventType type = EventType::input;  ///< What happened.
  std::int64_t frame = -1;   ///< Index of the source frame that produced it; -1: not tied to a frame (a device-level source error).
  double t = 0;              ///< That frame's timestamp from its source, s.
  double arrival_s = 0;      ///< When that frame arrived from the source, s, on clockSeconds().
  Input6 input;              ///< The 6-D input after filtering and shaping (mm, deg; FrameResult::input); zero out of contact.
  /// One standard deviation of each component of the measured 6-D input (FrameResult::sd), mm and deg;
  /// zero out of contact. An axis the pad cannot see (a turn while every contact marker slips) has a wide one.
  Input6 sd;
  ContactState state = ContactState::none;  ///< The contact state at this event.
  std::string message;       ///< Error events: one line saying what happened; empty otherwise.
};

/// What became of one frame.
enum class FrameStatus : std::uint8_t {
  ok = 0,         ///< Processed.
  reference = 1,  ///< This frame became the rest state (the first good frame, or the first after Sensor::reReference()).
  /// Unusable frame (wrong size, empty, or a candidate rest state with too few
  /// markers): FrameResult::message says why; when it was to be the rest state, the next frame is tried.
  skipped = 2,
  lost = 3,       ///< Too few markers found or tracked: FrameResult::message says why; no pose update.
};

/**
 * @brief The frame status's name.
 * @param s a frame status; a value outside the enumerators gives "lost".
 * @return "ok", "reference", "skipped" or "lost" (a static string).
 */
constexpr std::string_view toString(FrameStatus s) noexcept {
  switch (s) {
    case FrameStatus::ok: return "ok";
    case FrameStatus::reference: return "reference";
    case FrameStatus::skipped: return "skipped";
    case FrameStatus::lost: break;
  }
  return "lost";
}

/// Milliseconds spent on one frame, stage by stage.
struct StageTimes {
  double capture = 0, queue = 0, detect = 0, track = 0, triangulate = 0, contact = 0, pose = 0, process = 0;
  /// @var capture
  /// @brief The source's read of the frame (grab and decode), ms.
  /// @var queue
  /// @brief Waiting between capture and processing, ms.
  /// @var detect
  /// @brief Finding the markers in both views, ms.
  /// @var track
  /// @brief Tracking the markers from the previous frame, ms.
  /// @var triangulate
  /// @brief Stereo triangulation of the markers, ms.
  /// @var contact
  /// @brief Contact analysis (deformation field, regions), ms.
  /// @var pose
  /// @brief The 6-D pose and its events, ms.
  /// @var process
  /// @brief All of processing, detect to pose and events, ms.
};

/// One marker of the pattern grid in one frame (its index in FrameResult::markers is its id = row * cols + col).
struct MarkerState {
  bool valid = false;             ///< Triangulated in this frame; x, y, z hold a position only then.
  double x = 0, y = 0, z = 0;
  /// @var x
  /// @brief Position along S.x, mm (when valid).
  /// @var y
  /// @brief Position along S.y, mm (when valid).
  /// @var z
  /// @brief Position along S.z, mm (when valid).
  /** Valid now and at rest: the displacement ux, uy, uz is known. The rest is the reference frame's, kept
   *  true while nothing touches: it follows a camera shifted against the pad and slow drift (docs/pose). */
  bool displaced = false;
  double ux = 0, uy = 0, uz = 0;
  /// @var ux
  /// @brief Displacement from the rest position along S.x, mm (when displaced).
  /// @var uy
  /// @brief Displacement from the rest position along S.y, mm (when displaced).
  /// @var uz
  /// @brief Displacement from the rest position along S.z, mm (when displaced); -uz is the press depth here.
  int region = -1;                ///< The contact region (0 = the largest) it belongs to; -1 outside every region (or not displaced).
  /// Probability in [0, 1] that the marker moves with the finger (sticks) in this frame, from its drift off
  /// its anchor on the finger (docs/pose); 0 outside the tracked contact.
  double stick_probability = 0;
};

/// Everything the pipeline knows about one processed frame (Sensor::onFrame(), Sensor::pollFrame()).
struct FrameResult {
  std::int64_t frame = -1;   ///< Source frame index.
  double t = 0;              ///< The frame's timestamp from its source, s.
  double arrival_s = 0;      ///< When the frame arrived from the source, s, on clockSeconds().
  FrameStatus status = FrameStatus::skipped;  ///< What became of the frame.
  std::string message;       ///< Why, when skipped or lost; empty otherwise.
  bool contact = false;      ///< A finger touches the pad.
  ContactState state = ContactState::none;  ///< The contact state; none out of contact.
  Input6 raw;                ///< The measured 6-D input, mm and degrees (what `onetip process` writes to pose.csv).
  Input6 input;              ///< raw after the filter and the per-axis gain and dead zone (what events carry), mm and degrees.
  /// One standard deviation of each component of raw as the estimator knows it (pose.csv's sd_dx .. sd_roll),
  /// mm and degrees; zero out of contact. Directions the contact's sticking markers do not fix grow with time
  /// as the motion prior says (docs/pose).
  Input6 sd;
  bool pressed = false;      ///< The press button (SensorOptions::press_mm, SensorOptions::release_mm).
  bool out_of_range = false; ///< raw exceeded the working range (raw is then clamped to SensorOptions::clamp_factor times it).
  int rows = 0, cols = 0;
  /// @var rows
  /// @brief Rows of the marker grid; 0 when the frame was skipped or lost.
  /// @var cols
  /// @brief Columns of the marker grid; 0 when the frame was skipped or lost.
  std::vector<MarkerState> markers;  ///< rows * cols entries, indexed by marker id (the rest positions for a reference frame).
  int contact_regions = 0;   ///< Separate contact regions (fingers).
  double max_normal_mm = 0;  ///< The deepest normal deformation of the pad, mm.
  StageTimes times;          ///< Time spent on this frame per stage, ms.
};

}  // namespace onetip
