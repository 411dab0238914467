#include "input/press_button.hpp"

#include <cmath>

#include "core/error.hpp"

namespace onetip::input {

void PressButtonOptions::validate() const {
  if (!std::isfinite(press_mm) || !(press_mm > 0)) throw InputError("press button: press_mm must be a positive number");
  if (!std::isfinite(release_mm) || !(release_mm < press_mm))
    throw InputError("press button: release_mm must be a number below press_mm");
}

PressButton::PressButton(PressButtonOptions options) : options_(options) { options_.validate(); }

bool PressButton::update(double dz_mm) {
  const bool next = pressed_ ? !(dz_mm < options_.release_mm) : dz_mm > options_.press_mm;
  const bool changed = next != pressed_;
  pressed_ = next;
  return changed;
}

}  // namespace onetip::input
