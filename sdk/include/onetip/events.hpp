// onetip/events.hpp — what a running Sensor reports: discrete events and
// per-frame results.
//
// Frames and units (docs/reference.md): positions in millimetres in the sensor
// frame S (origin at the rest-state marker centroid, z out of the pad towards
// the finger, x along increasing marker column, y = z × x); angles in degrees;
// Input6 = [dx, dy, dz, yaw, pitch, roll], the finger's motion since contact
// onset (types.hpp). Times: `t` is the frame's own timestamp from its source
// (seconds: the driver's capture time for cameras, the scenario time for
// "sim:" sources, index / rate for folders); `arrival_s` is when the frame
// arrived from the source, on the steady clock of onetip::clockSeconds(), so
// `clockSeconds() - arrival_s` in a callback is the latency of that event.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "onetip/export.hpp"
#include "onetip/types.hpp"

namespace onetip {

// Seconds on a monotonic clock (std::chrono::steady_clock) shared by the
// library and its callers: the clock of Event::arrival_s and FrameResult::arrival_s.
ONETIP_EXPORT double clockSeconds() noexcept;

enum class EventType : std::uint8_t {
  contact_begin = 0,  // a contact starts; the 6-D input restarts from zero
  contact_end = 1,    // the contact ended; the 6-D input returns to zero (when its finger lifts while
                      // another stays on the pad, contact_begin for that one follows in the same frame)
  input = 2,          // the 6-D input of a frame in contact (every such frame)
  press = 3,          // the press button went down (dz rose above options.press_mm)
  release = 4,        // the press button went up (dz fell below options.release_mm)
  state_changed = 5,  // the contact state (none/stick/partial_slip/slip) differs from the previous frame's
  error = 6,          // something the caller should know: a source error, a frame that could not be
                      // used, too few markers, a callback that threw; `message` says what
};

// "contact_begin", "contact_end", "input", "press", "release", "state_changed", "error".
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

struct Event {
  EventType type = EventType::input;
  std::int64_t frame = -1;   // index of the source frame that produced it (-1: not tied to a frame)
  double t = 0;              // that frame's timestamp, s
  double arrival_s = 0;      // when that frame arrived from the source, s (clockSeconds())
  Input6 input;              // the 6-D input after filtering and shaping (mm, deg); zero out of contact
  ContactState state = ContactState::none;
  std::string message;       // error events: one line saying what happened
};

enum class FrameStatus : std::uint8_t {
  ok = 0,         // processed
  reference = 1,  // this frame became the rest state (the first frame, or after reReference())
  skipped = 2,    // unusable frame (wrong size, empty): message says why
  lost = 3,       // too few markers found or tracked: message says why; no pose update
};

// "ok", "reference", "skipped", "lost".
constexpr std::string_view toString(FrameStatus s) noexcept {
  switch (s) {
    case FrameStatus::ok: return "ok";
    case FrameStatus::reference: return "reference";
    case FrameStatus::skipped: return "skipped";
    case FrameStatus::lost: break;
  }
  return "lost";
}

// Milliseconds spent on one frame. capture: the source's next() (grab and
// decode); queue: waiting between capture and processing; detect .. pose: the
// processing stages; process: all of processing (detect to pose and events).
struct StageTimes {
  double capture = 0, queue = 0, detect = 0, track = 0, triangulate = 0, contact = 0, pose = 0, process = 0;
};

// One marker of the pattern grid in one frame (index = id = row * cols + col).
struct MarkerState {
  bool valid = false;             // triangulated in this frame
  double x = 0, y = 0, z = 0;     // position in S, mm (when valid)
  bool displaced = false;         // valid now and at rest: the displacement below is known
  double ux = 0, uy = 0, uz = 0;  // displacement from the rest position, S, mm; -uz is the press depth here
  int region = -1;                // contact region (0 = the largest) it belongs to, -1 outside every region
};

struct FrameResult {
  std::int64_t frame = -1;   // source frame index
  double t = 0;              // frame timestamp, s
  double arrival_s = 0;      // clockSeconds() at arrival
  FrameStatus status = FrameStatus::skipped;
  std::string message;       // why, when skipped or lost
  bool contact = false;
  ContactState state = ContactState::none;
  Input6 raw;                // the measured 6-D input (what `onetip process` writes to pose.csv)
  Input6 input;              // raw after the filter and per-axis gain / dead zone (what events carry)
  bool pressed = false;      // the press button
  bool out_of_range = false; // raw exceeded the working range (raw is clamped to clamp_factor times it)
  int rows = 0, cols = 0;    // the marker grid
  std::vector<MarkerState> markers;  // rows * cols entries, indexed by marker id
  int contact_regions = 0;   // separate contact regions (fingers)
  double max_normal_mm = 0;  // the deepest normal deformation of the pad, mm
  StageTimes times;
};

}  // namespace onetip
