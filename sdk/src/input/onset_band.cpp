#include "input/onset_band.hpp"

#include "core/option_checks.hpp"
#include "input/gel_recovery.hpp"

namespace onetip::input {

void OnsetBandOptions::validate() const {
  requireInRange("onset band: false_alarm", false_alarm, 1e-9, 0.1);
}

OnsetBand::OnsetBand(OnsetBandOptions options) : options_(options) { options_.validate(); }

void OnsetBand::reset() {
  have_last_ = false;
  last_mm_ = 0;
  armed_ = false;
}

double OnsetBand::halfWidth(int markers, double noise_mm) const {
  return noise_mm > 0 ? noise_mm * noiseMaximum(markers, options_.false_alarm) : 0.0;
}

bool OnsetBand::mayBegin(double max_modulus_mm, int markers, double noise_mm, double contact_threshold_mm) {
  if (!options_.enabled) return true;
  const double b = halfWidth(markers, noise_mm);
  const double m = max_modulus_mm;
  // Sank through the threshold this frame: the band noise can lift back over it begins.
  if (have_last_ && last_mm_ > contact_threshold_mm && m <= contact_threshold_mm) armed_ = true;
  have_last_ = true;
  last_mm_ = m;
  if (!armed_) return true;
  if (m < contact_threshold_mm - b || m > contact_threshold_mm + b) {
    armed_ = false;  // left the band: below it the field has gone, above it something pressed
    return true;
  }
  return false;
}

}  // namespace onetip::input
