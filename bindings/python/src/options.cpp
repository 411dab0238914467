// onetip.SensorOptions: how a Sensor runs. Its attributes are derived from the
// option table (onetip/sensor_option_table.hpp), one per row, with the row's
// type: int, float, bool, onetip.FilterKind (or its name) and, for axis
// arrays [dx, dy, dz, yaw, pitch, roll] (mm, deg), a list of 6 floats (read
// back as a new list: assign a whole list to change one, opts.gain = [...]).
// Assigning checks the value against the table's range (InputError naming
// the field, range and unit; the options are unchanged); validate() also
// checks the relations between options (release_mm < press_mm).
// SensorOptions.option_table() lists the rows.
#include <pybind11/stl.h>

#include <string>

#include "bindings.hpp"
#include "onetip/error.hpp"
#include "onetip/sensor_options.hpp"

namespace py = pybind11;

namespace onetip::python {
namespace {

const char* typeName(OptionType t) {
  switch (t) {
    case OptionType::integer:
      return "integer";
    case OptionType::real:
      return "real";
    case OptionType::flag:
      return "flag";
    case OptionType::choice:
      return "choice";
    case OptionType::axes:
      break;
  }
  return "axes";
}

// The Python value of a row from its values value(k), k < row.count.
template <typename Value>
py::object toPython(const OptionInfo& row, Value&& value) {
  switch (row.type) {
    case OptionType::integer:
      return py::int_(static_cast<long long>(value(0)));
    case OptionType::real:
      return py::float_(value(0));
    case OptionType::flag:
      return py::bool_(value(0) != 0);
    case OptionType::choice:
      return py::cast(static_cast<FilterKind>(static_cast<int>(value(0))));
    case OptionType::axes:
      break;
  }
  py::list list;
  for (int k = 0; k < row.count; ++k) list.append(py::float_(value(k)));
  return list;
}

double choiceValue(const OptionInfo& row, py::handle v) {
  if (py::isinstance<py::str>(v)) {
    const std::string name = v.cast<std::string>();
    std::string names;
    for (std::size_t c = 0; c < row.choices.size(); ++c) {
      if (name == row.choices[c]) return static_cast<double>(c);
      if (c > 0) names.append(", ");
      names.append(row.choices[c]);
    }
    throw Error(ErrorKind::input,
                "options." + std::string(row.name) + ": must be one of " + names + ", got '" + name + "'");
  }
  if (py::isinstance<py::int_>(v) && !py::isinstance<py::bool_>(v)) return static_cast<double>(v.cast<long long>());
  return static_cast<double>(static_cast<int>(v.cast<FilterKind>()));
}

// Sets a row from a Python value through the table's checks; `o` is unchanged on error.
void assign(SensorOptions& o, const OptionInfo& row, py::handle v) {
  SensorOptions next = o;
  switch (row.type) {
    case OptionType::integer:
      next.set(row.name, static_cast<double>(v.cast<long long>()));
      break;
    case OptionType::real:
      next.set(row.name, v.cast<double>());
      break;
    case OptionType::flag:
      next.set(row.name, v.cast<bool>() ? 1 : 0);
      break;
    case OptionType::choice:
      next.set(row.name, choiceValue(row, v));
      break;
    case OptionType::axes: {
      const auto values = v.cast<std::vector<double>>();
      if (static_cast<int>(values.size()) != row.count)
        throw Error(ErrorKind::input, "options." + std::string(row.name) + ": must be a list of " +
                                          std::to_string(row.count) + " numbers, got " + std::to_string(values.size()));
      for (int k = 0; k < row.count; ++k) next.set(row.name, values[static_cast<std::size_t>(k)], k);
      break;
    }
  }
  o = next;
}

// "<doc> (<type> in [min, max] <unit>)", numbers as Python prints them.
std::string docOf(const OptionInfo& row) {
  std::string doc(row.doc);
  doc.append(" (").append(typeName(row.type)).append(" in [");
  doc.append(py::str(py::float_(row.min)).cast<std::string>()).append(", ");
  doc.append(py::str(py::float_(row.max)).cast<std::string>()).append("]");
  if (*row.unit) doc.append(" ").append(row.unit);
  return doc.append(")");
}

void bindOptionInfo(py::module_& m) {
  py::class_<OptionInfo>(m, "OptionInfo", "One row of the option table (onetip/sensor_option_table.hpp).")
      .def_property_readonly("name", [](const OptionInfo& r) { return std::string(r.name); })
      .def_property_readonly(
          "type", [](const OptionInfo& r) { return std::string(typeName(r.type)); },
          "'integer', 'real', 'flag', 'choice' or 'axes' (6 values: dx, dy, dz, yaw, pitch, roll)")
      .def_property_readonly("count", [](const OptionInfo& r) { return r.count; })
      .def_property_readonly(
          "min", [](const OptionInfo& r) { return r.min; }, "closed range of every value")
      .def_property_readonly("max", [](const OptionInfo& r) { return r.max; })
      .def_property_readonly(
          "unit", [](const OptionInfo& r) { return std::string(r.unit); },
          "'' when none; 'mm|deg': mm for dx, dy, dz, degrees for yaw, pitch, roll")
      .def_property_readonly("doc", [](const OptionInfo& r) { return std::string(r.doc); })
      .def_property_readonly(
          "default",
          [](const OptionInfo& r) {
            return toPython(r, [&](int k) { return r.default_value[static_cast<std::size_t>(k)]; });
          },
          "in the attribute's Python type")
      .def_property_readonly("choices", [](const OptionInfo& r) {
        std::vector<std::string> names(r.choices.begin(), r.choices.end());
        return names;
      });
}

}  // namespace

void bindOptions(py::module_& m) {
  bindOptionInfo(m);
  py::class_<SensorOptions> options(m, "SensorOptions",
                                    "How a Sensor runs; one attribute per row of option_table(); validate() names the "
                                    "first bad field, load()/save() use YAML.");
  options.def(py::init([](const py::kwargs& fields) {
                SensorOptions o;
                py::object self = py::cast(o);
                for (const auto& [name, value] : fields) py::setattr(self, name, value);  // unknown names raise
                const SensorOptions result = self.cast<SensorOptions>();
                result.validate();  // the relations between options, here rather than in Sensor()
                return result;
              }),
              "Defaults, then each keyword sets the attribute of that name; InputError names a bad value.");
  for (const OptionInfo& row : SensorOptions::table()) {
    const OptionInfo* r = &row;  // the table has static storage
    options.def_property(
        row.name, [r](const SensorOptions& o) { return toPython(*r, [&](int k) { return o.get(r->name, k); }); },
        [r](SensorOptions& o, py::handle v) { assign(o, *r, v); }, docOf(row).c_str());
  }
  options.def("validate", &SensorOptions::validate, "Raises InputError naming the first bad field.")
      .def("__eq__", [](const SensorOptions& a, const SensorOptions& b) { return a == b; })
      .def_static(
          "option_table",
          [] { return std::vector<OptionInfo>(SensorOptions::table().begin(), SensorOptions::table().end()); },
          "The rows of the option table: name, type, count, min, max, unit, doc, default, choices.")
      .def_static(
          "load", [](const fs::path& path) { return SensorOptions::load(path.string()); }, py::arg("path"),
          "Reads a YAML/JSON options file (str or os.PathLike); InputError if it cannot.")
      .def(
          "save", [](const SensorOptions& o, const fs::path& path) { o.save(path.string()); }, py::arg("path"),
          "Writes every field as YAML (atomically).");
}

}  // namespace onetip::python
