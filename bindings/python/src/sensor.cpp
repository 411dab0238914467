// onetip.Sensor: the threaded pipeline (onetip/sensor.hpp) from Python.
//
// The GIL: every call that can block (opening the source, start, stop,
// waiting, replacing a callback, destruction) lets the GIL go, so the
// processing thread can run Python callbacks meanwhile; callbacks take the
// GIL (python_callable.hpp). Waits run in slices of at most 0.1 s and check
// for signals between them, so Ctrl-C interrupts a long wait_event().
// At interpreter exit every sensor still alive is stopped first, so no
// callback runs into a finalising interpreter.
#include <pybind11/stl.h>

#include <algorithm>
#include <functional>
#include <mutex>
#include <optional>
#include <set>

#include "bindings.hpp"
#include "onetip/sensor.hpp"
#include "python_callable.hpp"

namespace py = pybind11;

namespace onetip::python {
namespace {

constexpr double wait_slice_s = 0.1;

class PythonSensor;

// Sensors alive now, for the stop at interpreter exit.
struct LiveSensors {
  std::mutex mutex;
  std::set<PythonSensor*> sensors;
};
LiveSensors& liveSensors() {
  static LiveSensors* live = new LiveSensors;  // never destroyed: used until the very end
  return *live;
}

class PythonSensor {
 public:
  PythonSensor(const SensorConfig& config, const SensorOptions& options) {
    {
      py::gil_scoped_release nogil;
      sensor_ = std::make_unique<Sensor>(config, options);
    }
    std::lock_guard lock(liveSensors().mutex);
    liveSensors().sensors.insert(this);
  }
  PythonSensor(const PythonSensor&) = delete;
  PythonSensor& operator=(const PythonSensor&) = delete;
  ~PythonSensor() {
    {
      std::lock_guard lock(liveSensors().mutex);
      liveSensors().sensors.erase(this);
    }
    py::gil_scoped_release nogil;  // stopping waits for a callback that may want the GIL
    sensor_.reset();
  }

  Sensor& sensor() { return *sensor_; }

  // Stops and drops the callbacks (interpreter exit).
  void shutdown() {
    py::gil_scoped_release nogil;
    sensor_->onEvent({});
    sensor_->onFrame({});
    sensor_->stop();
  }

  std::optional<Event> waitEvent(double timeout_s) {
    for (double left = std::max(0.0, timeout_s);;) {
      Event e;
      const double slice = std::min(left, wait_slice_s);
      bool got = false, running = false;
      {
        py::gil_scoped_release nogil;
        got = sensor_->waitEvent(e, slice);
        running = sensor_->running();
      }
      if (got) return e;
      left -= slice;
      if (!running || left <= 0) return std::nullopt;
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    }
  }

  bool waitFinished(std::optional<double> timeout_s) {
    for (double left = timeout_s ? std::max(0.0, *timeout_s) : -1;;) {
      const double slice = left < 0 ? wait_slice_s : std::min(left, wait_slice_s);
      bool finished = false;
      {
        py::gil_scoped_release nogil;
        finished = sensor_->waitFinished(slice);
      }
      if (finished) return true;
      if (left >= 0 && (left -= slice) <= 0) return false;
      if (!sensor_->running()) return sensor_->finished();
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    }
  }

 private:
  std::unique_ptr<Sensor> sensor_;
};

void stopAllSensors() {
  std::set<PythonSensor*> sensors;
  {
    std::lock_guard lock(liveSensors().mutex);
    sensors = liveSensors().sensors;
  }
  for (PythonSensor* s : sensors) s->shutdown();
}

// Replaces a callback (None: removes it); waits for a call in progress, so without the GIL.
template <class Value, void (Sensor::*set)(std::function<void(const Value&)>)>
void setCallback(PythonSensor& s, const py::object& callback) {
  std::function<void(const Value&)> cb;
  if (!callback.is_none()) cb = pythonCallback<Value>(callback);
  py::gil_scoped_release nogil;
  (s.sensor().*set)(std::move(cb));
}

template <class Value>
std::optional<Value> polled(bool (Sensor::*poll)(Value&), Sensor& sensor) {
  Value v;
  if ((sensor.*poll)(v)) return v;
  return std::nullopt;
}

}  // namespace

void bindSensor(py::module_& m) {
  py::class_<PythonSensor>(m, "Sensor", R"(The fingertip sensor: a frame source and the threaded pipeline.

Sensor(source, calibration="", pattern="", reference="", options=None)
  source: "v4l2:/dev/videoN", a folder of images, a video file or "sim:SCENARIO.yaml".
  calibration, pattern: files (for "sim:" sources "" uses the simulator's own).
  reference: a rest-state image, or "" for the first frame.
Raises InputError naming the bad file, source or option.

Callbacks (on_event, on_frame) run on the processing thread, holding the GIL;
an exception they raise becomes an error event. Use as a context manager to
stop on exit.)")
      .def(py::init([](const fs::path& source, const fs::path& calibration, const fs::path& pattern,
                       const fs::path& reference, const std::optional<SensorOptions>& options) {
             return std::make_unique<PythonSensor>(
                 SensorConfig(source.string(), calibration.string(), pattern.string(), reference.string()),
                 options.value_or(SensorOptions{}));
           }),
           py::arg("source"), py::arg("calibration") = "", py::arg("pattern") = "", py::arg("reference") = "",
           py::arg("options") = py::none())
      .def("start", [](PythonSensor& s) { py::gil_scoped_release nogil; s.sensor().start(); },
           "Starts capture and processing (once; StateError after that).")
      .def("stop", [](PythonSensor& s) { py::gil_scoped_release nogil; s.sensor().stop(); },
           "Stops and waits for the callbacks to finish; queued events stay pollable. Idempotent.")
      .def_property_readonly("running", [](PythonSensor& s) { return s.sensor().running(); })
      .def_property_readonly("finished", [](PythonSensor& s) { return s.sensor().finished(); })
      .def_property_readonly("source", [](PythonSensor& s) { return s.sensor().source(); })
      .def("wait_finished", &PythonSensor::waitFinished, py::arg("timeout_s") = py::none(),
           "Waits until the source ended and every frame was processed (None: no limit); returns finished.")
      .def("on_event", &setCallback<Event, &Sensor::onEvent>, py::arg("callback"),
           "callback(Event) on the processing thread; None removes it.")
      .def("on_frame", &setCallback<FrameResult, &Sensor::onFrame>, py::arg("callback"),
           "callback(FrameResult) on the processing thread; None removes it.")
      .def("poll_event", [](PythonSensor& s) { return polled(&Sensor::pollEvent, s.sensor()); },
           "The oldest queued Event, or None (never blocks).")
      .def("poll_frame", [](PythonSensor& s) { return polled(&Sensor::pollFrame, s.sensor()); },
           "The oldest queued FrameResult, or None (never blocks).")
      .def("wait_event", &PythonSensor::waitEvent, py::arg("timeout_s"),
           "The next Event, waiting up to timeout_s seconds; None on time-out or once the sensor "
           "is not running and nothing is queued.")
      .def("rezero", [](PythonSensor& s) { s.sensor().reZero(); }, "The 6-D input restarts from zero next frame.")
      .def("rereference", [](PythonSensor& s) { s.sensor().reReference(); },
           "The next good frame becomes the rest state (finger off the pad).")
      .def("stats", [](PythonSensor& s) { return s.sensor().stats(); })
      .def("__enter__", [](PythonSensor& s) -> PythonSensor& { return s; }, py::return_value_policy::reference)
      .def("__exit__", [](PythonSensor& s, const py::args&) { py::gil_scoped_release nogil; s.sensor().stop(); });

  py::module_::import("atexit").attr("register")(py::cpp_function(&stopAllSensors));
}

}  // namespace onetip::python
