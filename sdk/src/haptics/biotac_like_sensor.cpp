#include "haptics/biotac_like_sensor.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/rotation.hpp"

namespace onetip::haptics {

namespace {
const FingertipShape kShape;  // the default: the BioTac-like ellipsoid
constexpr double kKernelSigmaMm = 2.5;
constexpr double kFluidLayerMm = 2.0;       // h0, conductive fluid between skin and core at rest
constexpr double kMinLayerFraction = 1e-3;  // asperities keep h >= h0 / 1000 (impedance range ~1000x)
constexpr double kPressureGain = 8.0;       // counts per mm^3 of indented volume
constexpr double kPressureBase = 500.0;

Eigen::Vector3d surfacePoint(double polar, double azimuth) {
  const Eigen::Vector3d u(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), -std::cos(polar));
  return kShape.centre + kShape.semi_axes.cwiseProduct(u);
}
}  // namespace

void BiotacLikeOptions::validate() const {
  if (!(noise_counts >= 0.0 && std::isfinite(noise_counts)))
    throw InputError("BiotacLikeOptions.noise_counts: must be finite and >= 0");
  if (polar_samples < 2 || polar_samples > 200) throw InputError("BiotacLikeOptions.polar_samples: must be in 2..200");
  if (azimuth_samples < 4 || azimuth_samples > 720)
    throw InputError("BiotacLikeOptions.azimuth_samples: must be in 4..720");
}

BiotacLikeSensor::BiotacLikeSensor(const BiotacLikeOptions& options) : options_(options), rng_(options.seed) {
  options_.validate();
  const double dt = 0.5 * M_PI / options_.polar_samples;
  const double dp = 2.0 * M_PI / options_.azimuth_samples;
  for (int i = 0; i < options_.polar_samples; ++i) {
    const double t = (i + 0.5) * dt;
    for (int j = 0; j < options_.azimuth_samples; ++j) {
      const double p = j * dp;
      const Eigen::Vector3d dq_dt = (surfacePoint(t + 1e-6, p) - surfacePoint(t - 1e-6, p)) / 2e-6;
      const Eigen::Vector3d dq_dp = (surfacePoint(t, p + 1e-6) - surfacePoint(t, p - 1e-6)) / 2e-6;
      samples_.push_back(surfacePoint(t, p));
      area_.push_back(dq_dt.cross(dq_dp).norm() * dt * dp);
      skin_area_ += area_.back();
    }
  }
  electrodes_.push_back(surfacePoint(0.0, 0.0));
  for (int j = 0; j < 6; ++j) electrodes_.push_back(surfacePoint(35.0 * kRadPerDeg, (60.0 * j + 30.0) * kRadPerDeg));
  for (int j = 0; j < 12; ++j) electrodes_.push_back(surfacePoint(68.0 * kRadPerDeg, 30.0 * j * kRadPerDeg));
  kernel_.resize(kElectrodes, static_cast<Eigen::Index>(samples_.size()));
  for (int e = 0; e < kElectrodes; ++e) {
    for (size_t k = 0; k < samples_.size(); ++k) {
      const double r2 = (samples_[k] - electrodes_[static_cast<size_t>(e)]).squaredNorm();
      kernel_(e, static_cast<Eigen::Index>(k)) = area_[k] * std::exp(-r2 / (2.0 * kKernelSigmaMm * kKernelSigmaMm));
    }
    kernel_.row(e) /= kernel_.row(e).sum();
  }
}

void BiotacLikeSensor::sense(const ContactPlane& plate, double* out) const {
  Eigen::VectorXd indent(static_cast<Eigen::Index>(samples_.size()));
  double volume = 0.0;
  for (size_t k = 0; k < samples_.size(); ++k) {
    const double d = std::max(0.0, -plate.normal.dot(samples_[k] - plate.point));
    indent(static_cast<Eigen::Index>(k)) = d;
    volume += area_[k] * d;
  }
  const Eigen::VectorXd electrode = kernel_ * indent;
  const double inflation = volume / skin_area_;  // the displaced fluid lifts the skin evenly
  std::normal_distribution<double> noise(0.0, 1.0);
  auto counts = [&](double v) {
    if (options_.noise_counts > 0.0) v += options_.noise_counts * noise(rng_);
    return std::clamp(std::round(v), 0.0, 4095.0);
  };
  for (int e = 0; e < kElectrodes; ++e) {
    const double layer = std::max(kFluidLayerMm * kMinLayerFraction, kFluidLayerMm - electrode(e) + inflation);
    const double impedance = kFluidLayerMm / layer;  // Z / Z0
    const double reference = 1.0 + 0.05 * (e % 5);   // R_j / Z0
    out[e] = counts(4095.0 * impedance / (impedance + reference));
  }
  out[kElectrodes] = counts(kPressureBase + kPressureGain * volume);
}

namespace {
BiotacLikeOptions withSeed(BiotacLikeOptions options, std::uint64_t seed) {
  options.seed = seed;
  return options;
}
}  // namespace

BiotacLikeEvaluationSensors::BiotacLikeEvaluationSensors(BiotacLikeOptions options)
    : collection(withSeed(options, 1)), remote(withSeed(options, 2)), in_device(withSeed(options, 3)) {}

}  // namespace onetip::haptics
