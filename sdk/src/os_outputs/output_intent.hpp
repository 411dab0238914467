// os_outputs/output_intent.hpp — what an OS-level output must do for each
// pipeline event (input/input_event.hpp), shared by the spnav server and the
// uinput joystick so both follow the same rules:
//   input          -> a motion with the event's 6-D vector (mm, degrees);
//   press          -> button 0 down (once; a repeated press is ignored);
//   release        -> button 0 up (only if it was down);
//   contact_end    -> button 0 up if it was still down, then an explicit rest
//                     motion (all zero, `rest` = true) so no client is left
//                     with a stale deflection;
//   contact_begin, state_changed, error -> nothing.
// period_ms is the time since the previous motion in milliseconds, rounded and
// clamped to [0, 1000]; 0 for the first motion or when timestamps go back or
// are not finite.
#pragma once

#include <vector>

#include "input/input_event.hpp"
#include "onetip/types.hpp"

namespace onetip::os_outputs {

struct OutputIntent {
  enum class Kind { motion, button } kind = Kind::motion;
  Input6 value;          // motion: the 6-D vector (zero when rest)
  bool rest = false;     // motion: the explicit zero after contact end
  int period_ms = 0;     // motion: ms since the previous motion
  bool press = false;    // button: true = down, false = up
};

class OutputTracker {
 public:
  // Not thread-safe: one caller at a time (the outputs lock around it).
  std::vector<OutputIntent> onEvent(const input::InputEvent& event);
  bool buttonDown() const noexcept { return button_down_; }

 private:
  OutputIntent motion(const Input6& value, double t, bool rest);
  bool button_down_ = false;
  bool have_last_motion_ = false;
  double last_motion_t_ = 0;
};

}  // namespace onetip::os_outputs
