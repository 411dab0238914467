// bindings.hpp — the parts of the Python module `onetip` (pybind11), one
// function per part, called in this order by module.cpp.
//
// The module mirrors the public C++ API (onetip/onetip.hpp) with Python
// names: positions in millimetres in the sensor frame S, angles in degrees,
// times in seconds; the 6-D input [dx, dy, dz, yaw, pitch, roll] is a numpy
// float64 array of shape (6,); marker sets are numpy arrays (arrays.hpp).
#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/stl/filesystem.h>  // file arguments accept str and os.PathLike (pathlib.Path)

#include <filesystem>

namespace onetip::python {

namespace fs = std::filesystem;

void bindErrors(pybind11::module_& m);        // errors.cpp: onetip.Error and its kinds
void bindValues(pybind11::module_& m);        // values.cpp: enums, Event, FrameResult, stats, clock, axes
void bindOptions(pybind11::module_& m);       // options.cpp: SensorOptions
void bindSensor(pybind11::module_& m);        // sensor.cpp: Sensor (threads, callbacks, the GIL)
void bindSimulatedSensor(pybind11::module_& m);  // simulated.cpp: SimulatedSensor, SimulatedFrame

}  // namespace onetip::python
