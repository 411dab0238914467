// haptics/biotac_like_sensor.hpp — a 20-channel BioTac-like sensor model:
// 19 electrode channels and one DC pressure channel, 12-bit counts.
//
// Geometry (device frame D, mm): the fingertip is the ellipsoid centred at
// C = (0, 0, a_z) with semi-axes (a_x, a_y, a_z) = (7, 11, 7), so its lowest
// point touches z = 0. Its surface below the equator is sampled at M points
// q_k (polar angle t from straight down in [0, 90] deg, azimuth p), each with
// area weight A_k. A plate (ContactPlane: point c, normal n into the finger)
// indents the skin at q_k by   delta_k = max(0, -n.(q_k - c))   (mm).
// Electrode j sits at the surface point of direction
//   u_j = (sin t_j cos p_j, sin t_j sin p_j, -cos t_j): one at the centre of the
//   pad, six at t = 35 deg, twelve at t = 68 deg (every 60 / 30 deg);
// it measures the impedance of the conductive fluid layer between the skin
// and the core above it. A thin layer of thickness h conducts like a sheet,
// so Z ~ 1 / h (the BioTac's nonlinear, steepening response):
//   delta_j = sum_k A_k K(|q_k - p_j|) delta_k / sum_k A_k K(...)   (local indentation,
//             Gaussian kernel K(r) = exp(-r^2 / (2 * 2.5^2)))
//   h_j     = max(h0 / 1000, h0 - delta_j + V / A_skin)   h0 = 2 mm of fluid at rest; the fluid
//             is incompressible, so the volume V pressed in lifts the skin evenly over its
//             sampled area A_skin (electrodes away from the contact read less); skin
//             asperities keep the layer from closing (an impedance range of ~1000x)
//   Z_j/Z0  = h0 / h_j
//   e_j     = 4095 * Z_j / (Z_j + R_j)   (a voltage divider with R_j = Z0 (1 + 0.05 (j mod 5)):
//             electrodes differ at rest, 1861-2048 counts, and saturate towards 4095).
// Small-signal gain at rest: 4095 / (4 h0) = 512 counts/mm, rising ~2.6x at 1.5 mm.
// The DC pressure channel follows the indented volume:
//   p_dc = 500 + g_p * sum_k A_k delta_k,  g_p = 8 counts/mm^3.
// Counts are rounded to integers and clamped to [0, 4095] (12 bits), plus
// optional Gaussian noise (noise_counts, deterministic per seed) before rounding.
// This is a stand-in with the BioTac's shape of data (smooth, coupled,
// saturating channels on a 3-D manifold of platform poses), not a model fitted
// to a real BioTac. With noise, sense() draws from an internal generator, so
// one instance must not be shared between threads.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <random>
#include <vector>

#include "haptics/tactile_sensor_model.hpp"

namespace onetip::haptics {

struct BiotacLikeOptions {
  double noise_counts = 0.0;  // Gaussian sensor noise, counts (>= 0)
  std::uint64_t seed = 1;
  int polar_samples = 12;  // surface sampling: rings from the pad to the equator
  int azimuth_samples = 36;
  void validate() const;  // throws InputError naming the bad field
};

class BiotacLikeSensor final : public TactileSensorModel {
 public:
  static constexpr int kElectrodes = 19;
  explicit BiotacLikeSensor(const BiotacLikeOptions& options = {});

  int channels() const override { return kElectrodes + 1; }
  void sense(const ContactPlane& plate, double* out) const override;
  using TactileSensorModel::sense;
  double fullScale(int) const override { return 4095.0; }

  const std::vector<Eigen::Vector3d>& electrodes() const noexcept { return electrodes_; }

 private:
  BiotacLikeOptions options_;
  std::vector<Eigen::Vector3d> samples_;  // q_k
  std::vector<double> area_;              // A_k
  double skin_area_ = 0.0;                // sum of A_k, mm^2
  Eigen::MatrixXd kernel_;                // 19 x M, rows normalised to sum 1
  std::vector<Eigen::Vector3d> electrodes_;
  mutable std::mt19937_64 rng_;
};

// The objective evaluation's three sensors: the one in the display during
// collection, the one in the remote environment and the one in the display
// during replay. Same model and options, independent noise (seeds 1, 2, 3).
struct BiotacLikeEvaluationSensors {
  explicit BiotacLikeEvaluationSensors(BiotacLikeOptions options);
  BiotacLikeSensor collection, remote, in_device;
};

}  // namespace onetip::haptics
