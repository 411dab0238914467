// sim/light_flicker.hpp — the LEDs' brightness changing from frame to frame:
// flicker (supply ripple beating with the exposure) and exposure steps (an
// auto-exposure decision, a driver changing the LED current).
//
// One gain per frame multiplies every grey level of both views before the
// sensor noise and the 8-bit rounding (it multiplies ImageEffects::exposure,
// sim/image_effects.hpp, so saturation clips it as it would a real sensor):
//   gain(t, k) = (1 + exposure_step [t >= step_at_s]) * (1 + flicker (2 U_k - 1))
// with U_k uniform on [0, 1), drawn from the run's seed and the frame index
// k alone (so a frame's gain does not depend on what was rendered before).
// flicker is the half-range of the per-frame gain (0.08: +-8 %),
// exposure_step a relative change (0.25: 25 % brighter, -0.3: 30 % darker).
// Image level only: the marker field does not depend on the light.
#pragma once

#include <cstdint>

namespace onetip::sim {

struct LightFlickerOptions {
  double flicker = 0;         // per-frame gain half-range, 0..0.5
  double exposure_step = 0;   // relative exposure change, -0.7..1
  double step_at_s = 0;       // when the step happens, 0..3600 s
  bool enabled() const { return flicker > 0 || exposure_step != 0; }
  double gain(double t, std::uint64_t seed, int frame_index) const;
  void validate() const;      // throws InputError naming the bad field
};

}  // namespace onetip::sim
