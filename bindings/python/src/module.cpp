// The Python module `onetip`: the fingertip sensor's pipeline, events and
// per-frame results (bindings.hpp lists the parts).
#include "bindings.hpp"
#include "onetip/version.hpp"

PYBIND11_MODULE(onetip, m) {
  m.doc() =
      "onetip: vision-based tactile 6-DoF fingertip input.\n\n"
      "Positions in mm in the sensor frame S, angles in degrees, times in seconds.\n"
      "The 6-D input is a numpy array [dx, dy, dz, yaw, pitch, roll].";
  m.attr("__version__") = onetip::versionString();
  onetip::python::bindErrors(m);
  onetip::python::bindValues(m);
  onetip::python::bindOptions(m);
  onetip::python::bindSensor(m);
  onetip::python::bindSimulatedSensor(m);
}
