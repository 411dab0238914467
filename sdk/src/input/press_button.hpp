// input/press_button.hpp — a button from the press depth, with hysteresis.
//
// Pressed when dz (mm, positive into the pad) rises above press_mm; released
// when it falls below release_mm (< press_mm), so noise near one threshold
// cannot make it chatter.
#pragma once

namespace onetip::input {

struct PressButtonOptions {
  double press_mm = 1.5;
  double release_mm = 1.0;
  void validate() const;  // throws InputError naming the bad field
};

class PressButton {
 public:
  explicit PressButton(PressButtonOptions options = {});
  // Returns true when the button state changed with this sample.
  bool update(double dz_mm);
  bool pressed() const { return pressed_; }
  void reset() { pressed_ = false; }

 private:
  PressButtonOptions options_;
  bool pressed_ = false;
};

}  // namespace onetip::input
