#include "input/press_button.hpp"

#include "core/option_checks.hpp"

namespace onetip::input {

void PressButtonOptions::validate() const {
  requireAbove("press button: press_mm", press_mm, 0, "mm");
  requireBelow("press button: release_mm", release_mm, "press_mm", press_mm);
}

PressButton::PressButton(PressButtonOptions options) : options_(options) { options_.validate(); }

bool PressButton::update(double dz_mm) {
  const bool next = pressed_ ? !(dz_mm < options_.release_mm) : dz_mm > options_.press_mm;
  const bool changed = next != pressed_;
  pressed_ = next;
  return changed;
}

}  // namespace onetip::input
