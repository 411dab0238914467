#include "sim/light_flicker.hpp"

#include <random>

#include "core/option_checks.hpp"

namespace onetip::sim {

namespace {
// U in [0, 1) from (seed, k) alone: a generator seeded by both (std::seed_seq
// mixes them), its first 32 bits.
double uniformOf(std::uint64_t seed, int k) {
  std::seed_seq mix{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                    static_cast<std::uint32_t>(k)};
  std::mt19937 rng(mix);
  return static_cast<double>(rng()) * 0x1.0p-32;
}
}  // namespace

double LightFlickerOptions::gain(double t, std::uint64_t seed, int frame_index) const {
  const double step = t >= step_at_s ? 1 + exposure_step : 1.0;
  const double ripple = flicker > 0 ? 1 + flicker * (2 * uniformOf(seed, frame_index) - 1) : 1.0;
  return step * ripple;
}

void LightFlickerOptions::validate() const {
  requireInRange("light: flicker", flicker, 0, 0.5);
  requireInRange("light: exposure_step", exposure_step, -0.7, 1);
  requireInRange("light: step_at_s", step_at_s, 0, 3600, "s");
}

}  // namespace onetip::sim
