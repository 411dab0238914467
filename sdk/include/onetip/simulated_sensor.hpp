/**
 * @file onetip/simulated_sensor.hpp
 * @brief The digital twin for application developers without hardware:
 * SimulatedSensor plays a scenario (samples/scenarios/\*.yaml, installed under
 * share/onetip/scenarios) and hands out each frame's camera image and exact
 * ground truth.
 *
 * Positions are in the sensor frame S (mm), angles in degrees, as in
 * docs/reference.md and types.hpp. To run the whole pipeline on a scenario,
 * open a Sensor with the source "sim:SCENARIO.yaml" instead.
 *
 * Thread rules: a SimulatedSensor is used by one thread at a time; distinct
 * objects are independent and may run on different threads concurrently.
 * Unlike the rest of the C++ API it reports bad input with std::runtime_error
 * (not onetip::Error).
 */
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "onetip/export.hpp"
#include "onetip/types.hpp"

namespace onetip {

/// One simulated frame: the camera image and the exact ground truth (SimulatedSensor::next()).
struct SimulatedFrame {
  int index = 0;                        ///< Frame index, from 0.
  double time_s = 0;                    ///< Scenario time of the frame, s.
  bool contact = false;                 ///< In contact: some marker is deformed by more than 0.1 mm.
  ContactState state = ContactState::none;  ///< The true contact state; none out of contact.
  Input6 truth;                         ///< The finger's true 6-D input, mm and degrees.
  std::vector<MarkerPoint> markers;     ///< Every marker of the pattern, by id, true position in S, mm.
  int width = 0, height = 0;
  /// @var width
  /// @brief Image width, pixels: both views side by side (0 when rendering is off).
  /// @var height
  /// @brief Image height, pixels (0 when rendering is off).
  std::vector<std::uint8_t> image;      ///< 8-bit grey, row-major, width * height bytes, both views side by side; empty when rendering is off.
};

/// How a SimulatedSensor plays its scenario.
struct SimulatedSensorOptions {
  bool render = true;  ///< false: ground truth only (fast, no image).
  int frames = 0;      ///< Frames to play, in [0, 1000000]; 0: the scenario's own count (duration * fps + 1).
  int seed = -1;       ///< Seed of the image noise and random poses, >= 0; -1: the scenario's seed.
};

/**
 * @brief Plays a simulator scenario frame by frame.
 *
 * Owns its simulator; not copyable. Each frame costs a physics step and,
 * when SimulatedSensorOptions::render is on, a rendering of the camera image.
 * Every member is called by one thread at a time (no internal locking);
 * distinct objects may run on different threads at once.
 */
class ONETIP_EXPORT SimulatedSensor {
 public:
  /**
   * @brief Loads the scenario and sets up the simulator.
   * @param scenario_path a scenario YAML file (samples/scenarios/press.yaml, ...).
   * @param options how to play it.
   * @throws std::runtime_error with a one-line message naming the bad input:
   *         a missing or malformed scenario file (file, line and key), or
   *         options out of range (frames, seed).
   */
  explicit SimulatedSensor(const std::string& scenario_path, const SimulatedSensorOptions& options = {});
  /// Frees the simulator.
  ~SimulatedSensor();
  SimulatedSensor(const SimulatedSensor&) = delete;             ///< Not copyable.
  SimulatedSensor& operator=(const SimulatedSensor&) = delete;  ///< Not copyable.

  /// @return the number of frames next() hands out in all (SimulatedSensorOptions::frames, or the scenario's own count).
  int frameCount() const;
  /**
   * @brief Advances to the next frame.
   * @param frame filled with the next frame (its vectors are resized and
   *        reused); untouched when there is none.
   * @return true when a frame was produced; false after the last one.
   */
  bool next(SimulatedFrame& frame);
  /**
   * @brief Writes the exact calibration and pattern files of the virtual
   * sensor, as SensorConfig::calibration and SensorConfig::pattern read them.
   * Each file is replaced atomically.
   * @param calib_path the calibration file to write (OpenCV FileStorage YAML).
   * @param pattern_path the pattern file to write (YAML: rows, cols, square_mm).
   * @throws std::runtime_error naming the path when a file cannot be written.
   */
  void saveCalibration(const std::string& calib_path, const std::string& pattern_path) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace onetip
