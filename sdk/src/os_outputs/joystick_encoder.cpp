#include "os_outputs/joystick_encoder.hpp"

#include <cstring>

#include "core/error.hpp"

namespace onetip::os_outputs {

namespace {
input_event makeEvent(int type, int code, std::int32_t value) {
  input_event e{};
  e.type = static_cast<__u16>(type);
  e.code = static_cast<__u16>(code);
  e.value = value;
  return e;
}
}  // namespace

void JoystickDeviceOptions::validate() const {
  if (name.empty() || name.size() >= UINPUT_MAX_NAME_SIZE) {
    throw InputError("joystick options: name: must be 1 to " + std::to_string(UINPUT_MAX_NAME_SIZE - 1) +
                     " bytes long");
  }
  range.validate();
}

JoystickDescription describeJoystick(const JoystickDeviceOptions& options) {
  options.validate();
  JoystickDescription d;
  d.setup.id.bustype = BUS_VIRTUAL;
  d.setup.id.vendor = options.vendor;
  d.setup.id.product = options.product;
  d.setup.id.version = options.version;
  std::memcpy(d.setup.name, options.name.c_str(), options.name.size() + 1);
  const auto rest = joystickAxes(Input6{}, options.range);
  for (size_t i = 0; i < d.axes.size(); ++i) {
    d.axes[i].code = static_cast<__u16>(kJoystickAxisCodes[i]);
    d.axes[i].absinfo.minimum = -kJoystickAxisMax;
    d.axes[i].absinfo.maximum = kJoystickAxisMax;
    d.axes[i].absinfo.value = rest[i];
  }
  d.keys = {kJoystickButton};
  return d;
}

JoystickEncoder::JoystickEncoder(const WorkingRange& range)
    : range_(range), axes_(joystickAxes(Input6{}, range)) {}

std::vector<input_event> JoystickEncoder::onEvent(const input::InputEvent& event) {
  std::vector<input_event> out;
  for (const OutputIntent& intent : tracker_.onEvent(event)) {
    if (intent.kind == OutputIntent::Kind::button) {
      out.push_back(makeEvent(EV_KEY, kJoystickButton, intent.press ? 1 : 0));
      continue;
    }
    const auto values = joystickAxes(intent.value, range_);
    for (size_t i = 0; i < values.size(); ++i) {
      if (values[i] == axes_[i]) continue;
      axes_[i] = values[i];
      out.push_back(makeEvent(EV_ABS, kJoystickAxisCodes[i], values[i]));
    }
  }
  if (!out.empty()) out.push_back(makeEvent(EV_SYN, SYN_REPORT, 0));
  return out;
}

}  // namespace onetip::os_outputs
