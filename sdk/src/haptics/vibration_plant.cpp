#include "haptics/vibration_plant.hpp"

#include <algorithm>
#include <cmath>

namespace onetip::haptics {

namespace {

// Analog biquad (n0 s^2 + n1 s + n2) / (s^2 + d1 s + d2) -> z by the bilinear
// transform pre-warped at f_warp: s = k (1 - z^-1) / (1 + z^-1).
struct Biquad {
  std::array<double, 3> b, a;
};
Biquad bilinear(double n0, double n1, double n2, double d1, double d2, double f_warp) {
  const double w = 2.0 * M_PI * f_warp;
  const double k = w / std::tan(w / (2.0 * kVibrationRateHz));
  const double k2 = k * k;
  const double a0 = k2 + d1 * k + d2;
  Biquad q;
  q.b = {(n0 * k2 + n1 * k + n2) / a0, (2.0 * n2 - 2.0 * n0 * k2) / a0, (n0 * k2 - n1 * k + n2) / a0};
  q.a = {1.0, (2.0 * d2 - 2.0 * k2) / a0, (k2 - d1 * k + d2) / a0};
  return q;
}
Biquad highPass(double f, double q) {
  const double w = 2 * M_PI * f;
  return bilinear(1.0, 0.0, 0.0, w / q, w * w, f);
}
Biquad lowPass(double f, double q) {
  const double w = 2 * M_PI * f;
  return bilinear(0.0, 0.0, w * w, w / q, w * w, f);
}
Biquad resonance(double f, double q_pole, double q_zero) {
  const double w = 2 * M_PI * f;
  return bilinear(1.0, w / q_zero, w * w, w / q_pole, w * w, f);
}

std::array<double, 7> multiply(const std::array<double, 3>& x, const std::array<double, 3>& y,
                               const std::array<double, 3>& z) {
  std::array<double, 5> xy{};
  for (size_t i = 0; i < 3; ++i)
    for (size_t j = 0; j < 3; ++j) xy[i + j] += x[i] * y[j];
  std::array<double, 7> out{};
  for (size_t i = 0; i < 5; ++i)
    for (size_t j = 0; j < 3; ++j) out[i + j] += xy[i] * z[j];
  return out;
}

}  // namespace

TransferFunction vibrationPlant(const PlatformPose& pose) {
  const double press = std::clamp(pose.z_mm, 0.0, 3.0);
  const double tilt = std::hypot(pose.roll_deg, pose.pitch_deg);
  const double f_r = 140.0 + 60.0 * press + 2.0 * tilt;
  const double q_pole = 3.0 + 1.5 * press;
  const double gain = 0.5 + 0.5 * press / 3.0;
  const Biquad hp = highPass(8.0, 0.707), res = resonance(f_r, q_pole, q_pole / 4.0), lp = lowPass(900.0, 0.6);
  TransferFunction tf;
  tf.b = multiply(hp.b, res.b, lp.b);
  tf.a = multiply(hp.a, res.a, lp.a);
  for (double& v : tf.b) v *= gain;
  return tf;
}

}  // namespace onetip::haptics
