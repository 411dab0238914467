// python_callable.hpp — a Python callable that the sensor's processing thread
// may call, and that any thread may destroy.
//
// The call takes the GIL, converts the argument to a Python object (a copy)
// and calls. A Python exception is turned into a std::runtime_error carrying
// its text, raised after the GIL is let go, so the Sensor counts it
// (SensorStats.callback_errors) and reports it as an error event. Destruction
// takes the GIL to drop the reference, so the holder may die on a thread that
// released it (Sensor.stop(), replacing a callback, the Sensor's destructor).
#pragma once

#include <pybind11/pybind11.h>

#include <memory>
#include <stdexcept>
#include <string>

namespace onetip::python {

class PythonCallable {
 public:
  explicit PythonCallable(pybind11::object function) : function_(std::move(function)) {}
  PythonCallable(const PythonCallable&) = delete;
  PythonCallable& operator=(const PythonCallable&) = delete;
  ~PythonCallable() {
    pybind11::gil_scoped_acquire gil;
    function_ = pybind11::object();
  }

  template <class Value>
  void operator()(const Value& value) const {
    std::string error;
    {
      pybind11::gil_scoped_acquire gil;
      try {
        function_(value);
      } catch (const pybind11::error_already_set& e) {
        error = e.what();
      }
    }
    if (!error.empty()) throw std::runtime_error("Python callback raised " + error);
  }

 private:
  pybind11::object function_;
};

// A copyable std::function target around one shared PythonCallable.
template <class Value>
auto pythonCallback(pybind11::object function) {
  auto callable = std::make_shared<PythonCallable>(std::move(function));
  return [callable](const Value& value) { (*callable)(value); };
}

}  // namespace onetip::python
