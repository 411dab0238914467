#include "arrays.hpp"

#include <limits>

namespace py = pybind11;

namespace onetip::python {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// An (n, 3) array filled per marker with `pick(marker, row)`.
template <class Pick>
py::array_t<double> perMarkerXyz(const std::vector<MarkerState>& markers, Pick pick) {
  py::array_t<double> out({static_cast<py::ssize_t>(markers.size()), py::ssize_t{3}});
  auto a = out.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) pick(markers[static_cast<size_t>(i)], &a(i, 0));
  return out;
}

void putRow(double* row, double a, double b, double c) {
  row[0] = a;
  row[1] = b;
  row[2] = c;
}

}  // namespace

py::array_t<double> input6Array(const Input6& v) {
  py::array_t<double> out(6);
  auto a = out.mutable_unchecked<1>();
  const auto values = v.asArray();
  for (py::ssize_t i = 0; i < 6; ++i) a(i) = values[static_cast<size_t>(i)];
  return out;
}

py::array_t<double> markerTable(const std::vector<MarkerState>& markers) {
  py::ssize_t n = 0;
  for (const MarkerState& s : markers) n += s.valid ? 1 : 0;
  py::array_t<double> out({n, py::ssize_t{4}});
  auto a = out.mutable_unchecked<2>();
  py::ssize_t row = 0;
  for (size_t id = 0; id < markers.size(); ++id) {
    const MarkerState& s = markers[id];
    if (!s.valid) continue;
    a(row, 0) = static_cast<double>(id);
    putRow(&a(row, 1), s.x, s.y, s.z);
    ++row;
  }
  return out;
}

py::array_t<double> markerTable(const std::vector<MarkerPoint>& markers) {
  py::array_t<double> out({static_cast<py::ssize_t>(markers.size()), py::ssize_t{4}});
  auto a = out.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) {
    const MarkerPoint& p = markers[static_cast<size_t>(i)];
    a(i, 0) = p.id;
    putRow(&a(i, 1), p.x, p.y, p.z);
  }
  return out;
}

py::array_t<double> markerPositions(const std::vector<MarkerState>& markers) {
  return perMarkerXyz(markers, [](const MarkerState& s, double* row) {
    if (s.valid)
      putRow(row, s.x, s.y, s.z);
    else
      putRow(row, nan, nan, nan);
  });
}

py::array_t<double> markerDisplacements(const std::vector<MarkerState>& markers) {
  return perMarkerXyz(markers, [](const MarkerState& s, double* row) {
    if (s.displaced)
      putRow(row, s.ux, s.uy, s.uz);
    else
      putRow(row, nan, nan, nan);
  });
}

}  // namespace onetip::python
