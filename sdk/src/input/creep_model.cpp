#include "input/creep_model.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>

namespace onetip::input {

void CreepModel::step(std::vector<Eigen::Vector3d>& v, const std::vector<Eigen::Vector3d>& u,
                      const std::vector<std::uint8_t>& valid, double dt) const {
  if (v.size() != u.size()) v.assign(u.size(), Eigen::Vector3d::Zero());
  const double a = std::exp(-std::max(dt, 0.0) / tau_c_s);
  const double load = (1 - a) * gain;
  for (size_t i = 0; i < v.size(); ++i)
    v[i] = valid[i] ? Eigen::Vector3d((a * v[i] + load * u[i]) / (1 + load)) : Eigen::Vector3d(a * v[i]);
}

std::string CreepModel::describe() const {
  char text[160];
  std::snprintf(text, sizeof text,
                "the gel's creep measured: %.0f %% of its modulus relaxes, relaxation time %.2f s; its recovery "
                "is no longer taken for a touch",
                100 * relaxedFraction(), relaxationTime());
  return text;
}

}  // namespace onetip::input
