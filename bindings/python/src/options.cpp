// onetip.SensorOptions: how a Sensor runs (onetip/sensor_options.hpp has the
// meaning, units and ranges of every field). Construct with keywords,
// SensorOptions(lossless=True, gain=[1, 1, 2, 1, 1, 1]); axis arrays are
// [dx, dy, dz, yaw, pitch, roll] (mm, deg) and read back as lists, so assign
// a whole list to change one (opts.gain = [...]).
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "onetip/sensor_options.hpp"

namespace py = pybind11;

namespace onetip::python {

void bindOptions(py::module_& m) {
  py::class_<SensorOptions> options(m, "SensorOptions",
                                    "How a Sensor runs; validate() names the first bad field, load()/save() use YAML.");
  options
      .def(py::init([](const py::kwargs& fields) {
             SensorOptions o;
             py::object self = py::cast(o);
             for (const auto& [name, value] : fields) py::setattr(self, name, value);  // unknown names raise
             const SensorOptions result = self.cast<SensorOptions>();
             result.validate();  // a bad value is refused here, not later by Sensor()
             return result;
           }),
           "Defaults, then each keyword sets the field of that name; InputError names a bad value.")
      .def_readwrite("queue_capacity", &SensorOptions::queue_capacity)
      .def_readwrite("lossless", &SensorOptions::lossless)
      .def_readwrite("playback_rate", &SensorOptions::playback_rate)
      .def_readwrite("event_queue_capacity", &SensorOptions::event_queue_capacity)
      .def_readwrite("frame_queue_capacity", &SensorOptions::frame_queue_capacity)
      .def_readwrite("timing_window", &SensorOptions::timing_window)
      .def_readwrite("max_consecutive_source_errors", &SensorOptions::max_consecutive_source_errors)
      .def_readwrite("stop_timeout_ms", &SensorOptions::stop_timeout_ms)
      .def_readwrite("min_markers", &SensorOptions::min_markers)
      .def_readwrite("working_range", &SensorOptions::working_range)
      .def_readwrite("clamp_factor", &SensorOptions::clamp_factor)
      .def_readwrite("press_mm", &SensorOptions::press_mm)
      .def_readwrite("release_mm", &SensorOptions::release_mm)
      .def_readwrite("gain", &SensorOptions::gain)
      .def_readwrite("dead_zone", &SensorOptions::dead_zone)
      .def_readwrite("filter", &SensorOptions::filter)
      .def_readwrite("filter_window", &SensorOptions::filter_window)
      .def_readwrite("filter_min_cutoff_hz", &SensorOptions::filter_min_cutoff_hz)
      .def_readwrite("filter_beta", &SensorOptions::filter_beta)
      .def_readwrite("filter_derivative_cutoff_hz", &SensorOptions::filter_derivative_cutoff_hz)
      .def("validate", &SensorOptions::validate, "Raises InputError naming the first bad field.")
      .def_static("load", [](const fs::path& path) { return SensorOptions::load(path.string()); }, py::arg("path"),
                  "Reads a YAML/JSON options file (str or os.PathLike); InputError if it cannot.")
      .def("save", [](const SensorOptions& o, const fs::path& path) { o.save(path.string()); }, py::arg("path"),
           "Writes every field as YAML (atomically).");
}

}  // namespace onetip::python
