#include "onetip/simulated_sensor.hpp"

#include "core/calibration.hpp"
#include "core/pattern.hpp"
#include "sim/simulator.hpp"

namespace onetip {

struct SimulatedSensor::Impl {
  std::unique_ptr<sim::Simulator> sim;
  bool render = true;
};

SimulatedSensor::SimulatedSensor(const std::string& scenario_path, const SimulatedSensorOptions& options)
    : impl_(std::make_unique<Impl>()) {
  sim::SimulatorOptions o;
  o.frames = options.frames;
  o.seed = options.seed;
  impl_->sim = std::make_unique<sim::Simulator>(sim::loadScenario(scenario_path), o);
  impl_->render = options.render;
}

SimulatedSensor::~SimulatedSensor() = default;

int SimulatedSensor::frameCount() const { return impl_->sim->frameCount(); }

bool SimulatedSensor::next(SimulatedFrame& out) {
  if (impl_->sim->done()) return false;
  const sim::GroundTruthFrame& f = impl_->sim->next();
  out.index = f.index;
  out.time_s = f.t;
  out.contact = f.in_contact;
  out.state = f.in_contact ? f.state : ContactState::none;
  out.truth = f.input;
  out.markers.resize(static_cast<size_t>(f.markers.size()));
  for (int id = 0; id < f.markers.size(); ++id) {
    const auto& p = f.markers.position[static_cast<size_t>(id)];
    out.markers[static_cast<size_t>(id)] = {id, p.x(), p.y(), p.z()};
  }
  if (impl_->render) {
    const cv::Mat img = impl_->sim->render();
    out.width = img.cols;
    out.height = img.rows;
    out.image.assign(img.datastart, img.dataend);
  } else {
    out.width = out.height = 0;
    out.image.clear();
  }
  return true;
}

void SimulatedSensor::saveCalibration(const std::string& calib_path, const std::string& pattern_path) const {
  onetip::saveCalibration(impl_->sim->calibration(), calib_path);
  savePattern(impl_->sim->pattern(), pattern_path);
}

}  // namespace onetip
