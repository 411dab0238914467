#include "os_outputs/output_intent.hpp"

#include <algorithm>
#include <cmath>

namespace onetip::os_outputs {

OutputIntent OutputTracker::motion(const Input6& value, double t, bool rest) {
  OutputIntent out;
  out.kind = OutputIntent::Kind::motion;
  out.value = value;
  out.rest = rest;
  if (have_last_motion_ && std::isfinite(t) && std::isfinite(last_motion_t_)) {
    out.period_ms = static_cast<int>(std::lround(std::clamp((t - last_motion_t_) * 1000.0, 0.0, 1000.0)));
  }
  have_last_motion_ = true;
  last_motion_t_ = t;
  return out;
}

std::vector<OutputIntent> OutputTracker::onEvent(const input::InputEvent& event) {
  using input::EventType;
  std::vector<OutputIntent> out;
  auto button = [&](bool press) {
    OutputIntent b;
    b.kind = OutputIntent::Kind::button;
    b.press = press;
    button_down_ = press;
    out.push_back(b);
  };
  switch (event.type) {
    case EventType::input:
      out.push_back(motion(event.input, event.t, false));
      break;
    case EventType::press:
      if (!button_down_) button(true);
      break;
    case EventType::release:
      if (button_down_) button(false);
      break;
    case EventType::contact_end:
      if (button_down_) button(false);
      out.push_back(motion(Input6{}, event.t, true));
      break;
    case EventType::contact_begin:
    case EventType::state_changed:
    case EventType::error:
      break;
  }
  return out;
}

}  // namespace onetip::os_outputs
