// The value types of the public API in Python: the enums, Event,
// FrameResult (its markers and contact field as numpy arrays, arrays.hpp),
// the sensor statistics, the shared clock and the joystick axis scaling
// (onetip/joystick_axes.hpp). All read-only snapshots.
#include <pybind11/stl.h>

#include <optional>
#include <sstream>

#include "arrays.hpp"
#include "bindings.hpp"
#include "onetip/joystick_axes.hpp"
#include "onetip/sensor.hpp"

namespace py = pybind11;

namespace onetip::python {
namespace {

using RangeRows = std::array<std::array<double, 2>, 6>;  // Python: six [lo, hi] pairs

AxisRanges toAxisRanges(const std::optional<RangeRows>& rows) {
  if (!rows) return defaultAxisRanges();
  AxisRanges r;
  for (size_t i = 0; i < r.size(); ++i) r[i] = {(*rows)[i][0], (*rows)[i][1]};
  return r;
}

py::array_t<double> rangeArray(const AxisRanges& r) {
  py::array_t<double> out({py::ssize_t{6}, py::ssize_t{2}});
  auto a = out.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < 6; ++i) {
    a(i, 0) = r[static_cast<size_t>(i)].lo;
    a(i, 1) = r[static_cast<size_t>(i)].hi;
  }
  return out;
}

py::dict stageTimes(const StageTimes& s) {
  py::dict d;
  d["capture"] = s.capture;
  d["queue"] = s.queue;
  d["detect"] = s.detect;
  d["track"] = s.track;
  d["triangulate"] = s.triangulate;
  d["contact"] = s.contact;
  d["pose"] = s.pose;
  d["process"] = s.process;
  return d;
}

void bindEnums(py::module_& m) {
  py::enum_<ContactState>(m, "ContactState", "The contact state of a frame.")
      .value("none", ContactState::none)
      .value("stick", ContactState::stick)
      .value("partial_slip", ContactState::partial_slip)
      .value("slip", ContactState::slip);
  py::enum_<EventType>(m, "EventType", "What an Event reports.")
      .value("contact_begin", EventType::contact_begin)
      .value("contact_end", EventType::contact_end)
      .value("input", EventType::input)
      .value("press", EventType::press)
      .value("release", EventType::release)
      .value("state_changed", EventType::state_changed)
      .value("error", EventType::error);
  py::enum_<FrameStatus>(m, "FrameStatus", "What became of a frame.")
      .value("ok", FrameStatus::ok)
      .value("reference", FrameStatus::reference)
      .value("skipped", FrameStatus::skipped)
      .value("lost", FrameStatus::lost);
  py::enum_<FilterKind>(m, "FilterKind", "Smoothing of the 6-D input.")
      .value("none", FilterKind::none)
      .value("moving_average", FilterKind::moving_average)
      .value("one_euro", FilterKind::one_euro);
}

void bindEvent(py::module_& m) {
  py::class_<Event>(m, "Event", "A discrete event of a running Sensor (onetip/events.hpp).")
      .def_readonly("type", &Event::type)
      .def_readonly("frame", &Event::frame, "index of the source frame (-1: not tied to a frame)")
      .def_readonly("t", &Event::t, "that frame's timestamp, s")
      .def_readonly("arrival_s", &Event::arrival_s, "when the frame arrived, s on clock_seconds()")
      .def_property_readonly(
          "input", [](const Event& e) { return input6Array(e.input); },
          "[dx, dy, dz, yaw, pitch, roll] (mm, deg), filtered and shaped; zero out of contact")
      .def_property_readonly(
          "sd", [](const Event& e) { return input6Array(e.sd); },
          "one standard deviation of each component of the measured 6-D input (FrameResult.sd; mm, deg); "
          "zero out of contact, wide for a component the pad cannot see")
      .def_readonly("state", &Event::state)
      .def_readonly("message", &Event::message, "error events: what happened")
      .def("__repr__", [](const Event& e) {
        std::ostringstream s;
        s << "<onetip.Event " << toString(e.type) << " frame=" << e.frame << " input=["
          << e.input.dx << ", " << e.input.dy << ", " << e.input.dz << ", " << e.input.yaw << ", " << e.input.pitch
          << ", " << e.input.roll << "]" << (e.message.empty() ? "" : " message=" + e.message) << ">";
        return s.str();
      });
}

void bindFrameResult(py::module_& m) {
  py::class_<FrameResult>(m, "FrameResult",
                          "The result of one frame. Marker arrays are indexed by marker id = row * cols + col.")
      .def_readonly("frame", &FrameResult::frame)
      .def_readonly("t", &FrameResult::t)
      .def_readonly("arrival_s", &FrameResult::arrival_s)
      .def_readonly("status", &FrameResult::status)
      .def_readonly("message", &FrameResult::message)
      .def_readonly("contact", &FrameResult::contact)
      .def_readonly("state", &FrameResult::state)
      .def_property_readonly("raw", [](const FrameResult& f) { return input6Array(f.raw); },
                             "the measured 6-D input (what `onetip process` writes to pose.csv)")
      .def_property_readonly("input", [](const FrameResult& f) { return input6Array(f.input); },
                             "raw after the filter, gain and dead zone (what events carry)")
      .def_property_readonly("sd", [](const FrameResult& f) { return input6Array(f.sd); },
                             "one standard deviation of each component of raw (pose.csv's sd_dx .. sd_roll; mm, deg); "
                             "zero out of contact, wide for a component the pad cannot see")
      .def_readonly("pressed", &FrameResult::pressed)
      .def_readonly("out_of_range", &FrameResult::out_of_range)
      .def_readonly("rows", &FrameResult::rows)
      .def_readonly("cols", &FrameResult::cols)
      .def_readonly("contact_regions", &FrameResult::contact_regions)
      .def_readonly("max_normal_mm", &FrameResult::max_normal_mm)
      .def_property_readonly("markers", [](const FrameResult& f) { return markerTable(f.markers); },
                             "(N, 4) float64 rows [id, x, y, z] of the triangulated markers, S, mm")
      .def_property_readonly("positions", [](const FrameResult& f) { return markerPositions(f.markers); },
                             "(rows*cols, 3) positions in S, mm; NaN where not triangulated")
      .def_property_readonly("displacements", [](const FrameResult& f) { return markerDisplacements(f.markers); },
                             "(rows*cols, 3) displacement from rest, S, mm; NaN where unknown "
                             "(reshape to (rows, cols, 3) for the contact field)")
      .def_property_readonly("valid", [](const FrameResult& f) { return markerField(f.markers, &MarkerState::valid); })
      .def_property_readonly("displaced",
                             [](const FrameResult& f) { return markerField(f.markers, &MarkerState::displaced); })
      .def_property_readonly(
          "regions", [](const FrameResult& f) { return markerField(f.markers, &MarkerState::region); },
          "(rows*cols,) int32 contact region per marker (0 = largest), -1 outside")
      .def_property_readonly(
          "stick_probability",
          [](const FrameResult& f) { return markerField(f.markers, &MarkerState::stick_probability); },
          "(rows*cols,) float64 per marker in [0, 1]: it moves with the finger (sticks) in this frame; "
          "0 outside the tracked contact")
      .def_property_readonly("times", [](const FrameResult& f) { return stageTimes(f.times); },
                             "milliseconds per stage: capture, queue, detect, ..., process");
}

void bindStats(py::module_& m) {
  py::class_<TimingSummary>(m, "TimingSummary", "Median, 99th percentile and maximum of one stage, ms.")
      .def_readonly("stage", &TimingSummary::stage)
      .def_readonly("count", &TimingSummary::count)
      .def_readonly("median_ms", &TimingSummary::median_ms)
      .def_readonly("p99_ms", &TimingSummary::p99_ms)
      .def_readonly("max_ms", &TimingSummary::max_ms);
  py::class_<SensorStats>(m, "SensorStats", "Counters and per-stage timing of a Sensor.")
      .def_readonly("frames_captured", &SensorStats::frames_captured)
      .def_readonly("frames_processed", &SensorStats::frames_processed)
      .def_readonly("frames_dropped", &SensorStats::frames_dropped)
      .def_readonly("frames_skipped", &SensorStats::frames_skipped)
      .def_readonly("frames_lost", &SensorStats::frames_lost)
      .def_readonly("source_errors", &SensorStats::source_errors)
      .def_readonly("events_emitted", &SensorStats::events_emitted)
      .def_readonly("events_dropped", &SensorStats::events_dropped)
      .def_readonly("frame_results_dropped", &SensorStats::frame_results_dropped)
      .def_readonly("callback_errors", &SensorStats::callback_errors)
      .def_readonly("source_abandoned", &SensorStats::source_abandoned)
      .def_readonly("stages", &SensorStats::stages);
}

void bindAxes(py::module_& m) {
  m.def("default_axis_ranges", [] { return rangeArray(defaultAxisRanges()); },
        "(6, 2) [lo, hi] per axis x, y, z (mm), rx, ry, rz (deg): the paper's working range");
  m.def(
      "joystick_axes",
      [](const std::array<double, 6>& input, const std::optional<RangeRows>& ranges) {
        return joystickAxes(Input6::fromArray(input), toAxisRanges(ranges));
      },
      py::arg("input"), py::arg("ranges") = py::none(),
      "The 6-D input as six int joystick axes x, y, z, rx, ry, rz in [-32767, 32767], "
      "scaled like `onetip joystick` (onetip/joystick_axes.hpp).");
  m.def(
      "spnav_axes",
      [](const std::array<double, 6>& input, const std::optional<RangeRows>& ranges, double full_scale) {
        return spnavAxes(Input6::fromArray(input), toAxisRanges(ranges), full_scale);
      },
      py::arg("input"), py::arg("ranges") = py::none(), py::arg("full_scale") = 350.0,
      "The 6-D input as the six spacenavd motion values of `onetip spnav`.");
}

}  // namespace

void bindValues(py::module_& m) {
  bindEnums(m);
  bindEvent(m);
  bindFrameResult(m);
  bindStats(m);
  bindAxes(m);
  m.def("clock_seconds", &clockSeconds, "Seconds on the monotonic clock of Event.arrival_s.");
}

}  // namespace onetip::python
