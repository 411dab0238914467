// onetip/simulated_sensor.hpp — the digital twin for application developers
// without hardware: plays a scenario (samples/scenarios/*.yaml) and hands out
// each frame's camera image and exact ground truth.
//
// Positions are in the sensor frame S (mm), angles in degrees, as in
// docs/reference.md. Thread-safety: one SimulatedSensor per thread; distinct
// objects are independent.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "onetip/export.hpp"
#include "onetip/types.hpp"

namespace onetip {

struct SimulatedFrame {
  int index = 0;
  double time_s = 0;
  bool contact = false;                 // by the 0.1 mm deformation rule
  ContactState state = ContactState::none;
  Input6 truth;                         // the finger's true 6-D input
  std::vector<MarkerPoint> markers;     // every marker, S, mm
  int width = 0, height = 0;            // image size (0 when render is off)
  std::vector<std::uint8_t> image;      // 8-bit grey, row-major, both views side by side
};

struct SimulatedSensorOptions {
  bool render = true;  // false: field level only (fast, no image)
  int frames = 0;      // 0: the scenario's own frame count
  int seed = -1;       // -1: the scenario's seed
};

class ONETIP_EXPORT SimulatedSensor {
 public:
  // Throws std::runtime_error with a one-line message naming the bad input.
  explicit SimulatedSensor(const std::string& scenario_path, const SimulatedSensorOptions& options = {});
  ~SimulatedSensor();
  SimulatedSensor(const SimulatedSensor&) = delete;
  SimulatedSensor& operator=(const SimulatedSensor&) = delete;

  int frameCount() const;
  // Fills `frame` with the next frame; false after the last one.
  bool next(SimulatedFrame& frame);
  // Writes the exact calibration and pattern files of the virtual sensor.
  void saveCalibration(const std::string& calib_path, const std::string& pattern_path) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace onetip
