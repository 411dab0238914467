#include "haptics/remote_interactions.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/rotation.hpp"

namespace onetip::haptics {

namespace {

constexpr double kClearMm = -0.5;

// Cosine blend from a to b as u goes from u0 to u1.
double blend(double u, double u0, double u1, double a, double b) {
  const double t = std::clamp((u - u0) / (u1 - u0), 0.0, 1.0);
  return a + (b - a) * 0.5 * (1.0 - std::cos(M_PI * t));
}

ContactPlane plate(const Eigen::Vector3d& normal, double depth, const FingertipShape& shape) {
  ContactPlane p;
  p.normal = normal.normalized();
  const double support = shape.semi_axes.cwiseProduct(p.normal).norm();
  p.point = shape.centre - p.normal * (support - depth);
  return p;
}

Eigen::Vector3d sideNormal(RemoteInteraction side, double tilt_rad) {
  const double s = std::sin(tilt_rad), c = std::cos(tilt_rad);
  switch (side) {
    case RemoteInteraction::back_flat_back: return {0.0, s, c};
    case RemoteInteraction::tip_flat_tip: return {0.0, -s, c};
    case RemoteInteraction::left_flat_left: return {s, 0.0, c};
    case RemoteInteraction::right_flat_right: return {-s, 0.0, c};
    default: break;
  }
  return Eigen::Vector3d::UnitZ();
}

ContactPlane oneRepetition(RemoteInteraction kind, double u, const InteractionOptions& o,
                           const FingertipShape& shape) {
  if (kind == RemoteInteraction::flat) {
    const double depth = u < 0.5 ? blend(u, 0.0, 0.3, kClearMm, 1.3 * o.press_mm)
                                 : blend(u, 0.7, 1.0, 1.3 * o.press_mm, kClearMm);
    return plate(Eigen::Vector3d::UnitZ(), depth, shape);
  }
  const double side = o.side_tilt_deg * kRadPerDeg;
  const double depth = u < 0.5 ? blend(u, 0.0, 0.15, kClearMm, o.press_mm) : blend(u, 0.85, 1.0, o.press_mm, kClearMm);
  const double tilt = u < 0.5 ? blend(u, 0.15, 0.5, side, 0.0) : blend(u, 0.5, 0.85, 0.0, side);
  return plate(sideNormal(kind, tilt), depth, shape);
}

}  // namespace

std::string_view toString(RemoteInteraction interaction) {
  switch (interaction) {
    case RemoteInteraction::back_flat_back: return "back-flat-back";
    case RemoteInteraction::tip_flat_tip: return "tip-flat-tip";
    case RemoteInteraction::left_flat_left: return "left-flat-left";
    case RemoteInteraction::right_flat_right: return "right-flat-right";
    case RemoteInteraction::flat: return "flat";
    case RemoteInteraction::complex: break;
  }
  return "complex";
}

void InteractionOptions::validate() const {
  if (!(rate_hz > 0.0 && rate_hz <= 10000.0)) throw InputError("InteractionOptions.rate_hz: must be in (0, 10000]");
  if (repetitions < 1 || repetitions > 100) throw InputError("InteractionOptions.repetitions: must be in 1..100");
  if (!(repetition_s > 0.0 && repetition_s <= 600.0))
    throw InputError("InteractionOptions.repetition_s: must be in (0, 600]");
  if (!(press_mm > 0.0 && press_mm <= 5.0)) throw InputError("InteractionOptions.press_mm: must be in (0, 5]");
  if (!(side_tilt_deg >= 0.0 && side_tilt_deg <= 85.0))
    throw InputError("InteractionOptions.side_tilt_deg: must be in [0, 85]");
}

std::vector<ContactPlane> remoteInteraction(RemoteInteraction interaction, const InteractionOptions& o,
                                            const FingertipShape& shape) {
  o.validate();
  const int per_repetition = std::max(2, static_cast<int>(std::lround(o.repetition_s * o.rate_hz)));
  std::vector<RemoteInteraction> parts = {interaction};
  if (interaction == RemoteInteraction::complex)
    parts.assign(kRemoteInteractions.begin(), kRemoteInteractions.begin() + 5);
  std::vector<ContactPlane> out;
  for (int r = 0; r < o.repetitions; ++r)
    for (RemoteInteraction part : parts)
      for (int k = 0; k < per_repetition; ++k)
        out.push_back(oneRepetition(part, static_cast<double>(k) / (per_repetition - 1), o, shape));
  return out;
}

}  // namespace onetip::haptics
