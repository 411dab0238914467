// input/input_event.hpp — what the pose tracker reports besides the 6-D signal.
//
// contact_begin / contact_end: a contact starts (the 6-D signal is re-zeroed)
// or ends; input: the 6-D vector, every frame in contact; press / release: the
// press button (press_button.hpp); state_changed: the contact state
// (none, stick, partial_slip, slip) differs from the previous frame's;
// error: something the caller should know (too few markers, solver failure,
// a motion limited for safety, the working range exceeded), with a message.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "onetip/types.hpp"

namespace onetip::input {

enum class EventType : std::uint8_t { contact_begin, contact_end, input, press, release, state_changed, error };

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

struct InputEvent {
  EventType type = EventType::input;
  double t = 0;                          // seconds
  Input6 input;                          // the output 6-D vector at t
  ContactState state = ContactState::none;
  std::string message;                   // error events
};

}  // namespace onetip::input
