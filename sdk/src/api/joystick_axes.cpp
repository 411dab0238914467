#include "onetip/joystick_axes.hpp"

#include "api/public_error.hpp"
#include "os_outputs/axis_scaling.hpp"

namespace onetip {
namespace {

os_outputs::WorkingRange toInternal(const AxisRanges& range) {
  os_outputs::WorkingRange r;
  for (size_t k = 0; k < range.size(); ++k) r.axes[k] = {range[k].lo, range[k].hi};
  return r;
}

}  // namespace

AxisRanges defaultAxisRanges() noexcept {
  const os_outputs::WorkingRange r;
  AxisRanges out;
  for (size_t k = 0; k < out.size(); ++k) out[k] = {r.axes[k].lo, r.axes[k].hi};
  return out;
}

std::array<std::int32_t, 6> joystickAxes(const Input6& input, const AxisRanges& range) {
  return api::withPublicErrors([&] {
    const os_outputs::WorkingRange r = toInternal(range);
    r.validate();
    return os_outputs::joystickAxes(input, r);
  });
}

std::array<std::int32_t, 6> spnavAxes(const Input6& input, const AxisRanges& range, double full_scale) {
  return api::withPublicErrors([&] {
    const os_outputs::WorkingRange r = toInternal(range);
    r.validate();
    if (!(full_scale > 0 && full_scale <= 1e6)) throw Error(ErrorKind::input, "spnav full_scale: must be in (0, 1e6]");
    return os_outputs::spnavAxes(input, r, full_scale);
  });
}

}  // namespace onetip
