// onetip.SimulatedSensor: the digital twin (onetip/simulated_sensor.hpp),
// each frame's camera image as a numpy uint8 (height, width) array and its
// exact ground truth (markers (N, 4) [id, x, y, z] in S, mm; truth (6,)).
// Construction errors (a bad scenario) raise InputError.
#include <pybind11/stl.h>

#include <optional>

#include "arrays.hpp"
#include "bindings.hpp"
#include "onetip/error.hpp"
#include "onetip/simulated_sensor.hpp"

namespace py = pybind11;

namespace onetip::python {
namespace {

py::object imageArray(const SimulatedFrame& f) {
  if (f.width <= 0 || f.height <= 0) return py::none();
  py::array_t<std::uint8_t> out({static_cast<py::ssize_t>(f.height), static_cast<py::ssize_t>(f.width)});
  std::copy(f.image.begin(), f.image.end(), out.mutable_data());
  return out;
}

std::unique_ptr<SimulatedSensor> openSimulation(const std::string& path, const SimulatedSensorOptions& options) {
  try {
    return std::make_unique<SimulatedSensor>(path, options);
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {  // documented as std::runtime_error naming the bad input
    throw Error(ErrorKind::input, e.what());
  }
}

}  // namespace

void bindSimulatedSensor(py::module_& m) {
  py::class_<SimulatedFrame>(m, "SimulatedFrame", "One simulated frame and its ground truth.")
      .def_readonly("index", &SimulatedFrame::index)
      .def_readonly("time_s", &SimulatedFrame::time_s)
      .def_readonly("contact", &SimulatedFrame::contact)
      .def_readonly("state", &SimulatedFrame::state)
      .def_property_readonly("truth", [](const SimulatedFrame& f) { return input6Array(f.truth); },
                             "the finger's true [dx, dy, dz, yaw, pitch, roll] (mm, deg)")
      .def_property_readonly("markers", [](const SimulatedFrame& f) { return markerTable(f.markers); },
                             "(N, 4) rows [id, x, y, z], every marker, S, mm")
      .def_property_readonly("image", &imageArray, "uint8 (height, width), both views; None when not rendered");

  py::class_<SimulatedSensor>(m, "SimulatedSensor", "Plays a scenario (samples/scenarios/*.yaml) frame by frame.")
      .def(py::init([](const fs::path& scenario, bool render, int frames, int seed) {
             py::gil_scoped_release nogil;
             return openSimulation(scenario.string(), SimulatedSensorOptions{render, frames, seed});
           }),
           py::arg("scenario"), py::arg("render") = true, py::arg("frames") = 0, py::arg("seed") = -1)
      .def_property_readonly("frame_count", &SimulatedSensor::frameCount)
      .def(
          "next",
          [](SimulatedSensor& s) -> std::optional<SimulatedFrame> {
            SimulatedFrame f;
            py::gil_scoped_release nogil;
            if (s.next(f)) return f;
            return std::nullopt;
          },
          "The next SimulatedFrame, or None after the last.")
      .def(
          "save_calibration",
          [](const SimulatedSensor& s, const fs::path& calibration, const fs::path& pattern) {
            s.saveCalibration(calibration.string(), pattern.string());
          },
          py::arg("calibration_path"), py::arg("pattern_path"),
           "Writes the virtual sensor's exact calibration and pattern files.");
}

}  // namespace onetip::python
