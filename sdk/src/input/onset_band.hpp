// input/onset_band.hpp — a field that sinks through the contact threshold
// starts no contact from noise: after it, a contact begins only when the
// field rises beyond what the markers' noise can add.
//
// The contact rule (contact/contact_analyzer.hpp) cuts the largest
// deformation modulus m = max_i |u_i| (u_i = p_i - r_i against the kept rest,
// S, mm) at the contact threshold T. A field that decays slowly through T (a
// creeping gel's delayed part after a lift-off, a recovery that sinks below
// T: gel_recovery.hpp) sits near T for many frames, and noise moves m across
// it both ways: each upward crossing would begin a contact while nothing
// touches. With sigma the measured marker noise per axis, the noisiest axis's
// (pose/sensor_self_model.hpp: largest_axis_noise_mm) and N markers measured, the noise lifts m
// above its noiseless value by at most the largest noise vector,
//   |u_i + n_i| <= |u_i| + |n_i|,   max_i |n_i| <= b = sigma noiseMaximum(N, p)
// with probability 1 - p per frame (gel_recovery.hpp's noiseMaximum: three
// unit-normal components each). So once m has sunk through T (m_{k-1} > T >=
// m_k), until it is below T - b (it has left the band noise can lift over T),
// a contact may begin only when m > T + b: a finger pressing again raises
// the field beyond that, a decaying field does so with probability below p.
// Outside that band the contact rule alone decides, so a press from rest
// begins at T as before. The bar is passed or left, and the band forgotten,
// when m leaves it on either side.
// Only onsets are gated (a contact in progress ends and goes on by the
// contact rule): the caller clears an onset frame's contact when
// mayBegin() says no. Every bound is a multiple of the measured noise.
#pragma once

namespace onetip::input {

struct OnsetBandOptions {
  bool enabled = true;
  double false_alarm = 1e-3;  // [1e-9, 0.1] per frame: chance that noise lifts a sunk field beyond the bar
  void validate() const;      // throws InputError naming the bad field
};

class OnsetBand {
 public:
  explicit OnsetBand(OnsetBandOptions options = {});
  // This frame's largest deformation modulus (mm) over `markers` measured markers, the measured noise per axis
  // (mm) and the contact threshold (mm). Call once per analysed frame. True when a contact may begin now.
  bool mayBegin(double max_modulus_mm, int markers, double noise_mm, double contact_threshold_mm);
  // The bar's half-width b = sigma noiseMaximum(N, p) (mm).
  double halfWidth(int markers, double noise_mm) const;
  void reset();

 private:
  OnsetBandOptions options_;
  bool have_last_ = false;
  double last_mm_ = 0;
  bool armed_ = false;
};

}  // namespace onetip::input
