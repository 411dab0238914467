#include "sim/viscoelastic_layer.hpp"

#include <cmath>
#include <stdexcept>

#include "core/option_checks.hpp"

namespace onetip::sim {

void ViscoelasticOptions::validate() const {
  requireInRange("viscoelastic: relaxation", relaxation, 0, 0.6);
  requireInRange("viscoelastic: time_s", time_s, 0.01, 60, "s");
}

ViscoelasticLayer::ViscoelasticLayer(const ViscoelasticOptions& options, int nodes)
    : options_(options),
      delayed_(static_cast<size_t>(nodes), Eigen::Vector3d::Zero()),
      total_(static_cast<size_t>(nodes), Eigen::Vector3d::Zero()) {
  options_.validate();
}

const std::vector<Eigen::Vector3d>& ViscoelasticLayer::advance(const std::vector<Eigen::Vector3d>& elastic,
                                                                double dt) {
  if (elastic.size() != delayed_.size()) throw std::logic_error("ViscoelasticLayer::advance: node count changed");
  if (!(dt >= 0)) throw std::logic_error("ViscoelasticLayer::advance: time went backwards");
  const double a = std::exp(-dt / options_.retardationTime());
  const double gain = (1 - a) * options_.creepGain();
  for (size_t i = 0; i < elastic.size(); ++i) {
    delayed_[i] = a * delayed_[i] + gain * elastic[i];
    total_[i] = elastic[i] + delayed_[i];
  }
  return total_;
}

}  // namespace onetip::sim
