#include "sim/camera_shift.hpp"

#include <algorithm>

#include "core/option_checks.hpp"

namespace onetip::sim {

Eigen::Vector2d CameraShiftOptions::shiftAt(double t, int view) const {
  if ((views == Views::left && view != 0) || (views == Views::right && view != 1)) return Eigen::Vector2d::Zero();
  if (t < at_s) return Eigen::Vector2d::Zero();
  const double progress = ramp_s > 0 ? std::min(1.0, (t - at_s) / ramp_s) : 1.0;
  return progress * shift_px;
}

void CameraShiftOptions::validate() const {
  requireInRange("camera_shift: px[0]", shift_px.x(), -100, 100, "px");
  requireInRange("camera_shift: px[1]", shift_px.y(), -100, 100, "px");
  requireInRange("camera_shift: at_s", at_s, 0, 3600, "s");
  requireInRange("camera_shift: ramp_s", ramp_s, 0, 3600, "s");
}

bool cameraShiftViewsFromString(std::string_view name, CameraShiftOptions::Views& out) {
  if (name == "both") out = CameraShiftOptions::Views::both;
  else if (name == "left") out = CameraShiftOptions::Views::left;
  else if (name == "right") out = CameraShiftOptions::Views::right;
  else return false;
  return true;
}

}  // namespace onetip::sim
