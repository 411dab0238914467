// input/input_event.hpp — what the pose tracker reports besides the 6-D signal.
//
// contact_begin / contact_end: a contact starts (the 6-D signal is re-zeroed)
// or ends; input: the 6-D vector, every frame in contact; press / release: the
// press button (press_button.hpp); state_changed: the contact state
// (none, stick, partial_slip, slip) differs from the previous frame's;
// error: something the caller should know (too few markers, solver failure,
// a motion limited for safety, the working range exceeded, the camera moved,
// markers hidden for good, the gel's creep measured), with a message.
#pragma once

#include <string>

#include "onetip/events.hpp"
#include "onetip/types.hpp"

namespace onetip::input {

// The event kinds are the public API's (onetip/events.hpp), so the values
// and their names are defined once.
using EventType = ::onetip::EventType;

struct InputEvent {
  EventType type = EventType::input;
  double t = 0;                          // seconds
  Input6 input;                          // the output 6-D vector at t
  Input6 sd;                             // one standard deviation of the measured vector (mm, deg)
  ContactState state = ContactState::none;
  std::string message;                   // error events
};

}  // namespace onetip::input
