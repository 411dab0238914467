// arrays.hpp — onetip values as numpy arrays (always copies: the arrays own
// their data and stay valid after the sensor moves on).
//
//   input6Array:     Input6 -> float64 (6,) [dx, dy, dz (mm), yaw, pitch, roll (deg)]
//   markerTable:     the valid markers -> float64 (N, 4) rows [id, x, y, z] (S, mm), ids ascending
//   markerPositions: every marker id -> float64 (rows*cols, 3) position in S, NaN where not triangulated
//   markerDisplacements: every marker id -> float64 (rows*cols, 3) displacement from rest (S, mm),
//                    NaN where unknown; reshape to (rows, cols, 3) for the contact field
//   markerField:     one field of every marker id -> (rows*cols,) of its type: bool valid or
//                    displaced, int32 contact region (-1: none), float64 stick probability
#pragma once

#include <pybind11/numpy.h>

#include <vector>

#include "onetip/events.hpp"
#include "onetip/types.hpp"

namespace onetip::python {

pybind11::array_t<double> input6Array(const Input6& v);
pybind11::array_t<double> markerTable(const std::vector<MarkerState>& markers);
pybind11::array_t<double> markerTable(const std::vector<MarkerPoint>& markers);
pybind11::array_t<double> markerPositions(const std::vector<MarkerState>& markers);
pybind11::array_t<double> markerDisplacements(const std::vector<MarkerState>& markers);

template <typename T>
pybind11::array_t<T> markerField(const std::vector<MarkerState>& markers, T MarkerState::*field) {
  pybind11::array_t<T> out(static_cast<pybind11::ssize_t>(markers.size()));
  auto a = out.template mutable_unchecked<1>();
  for (pybind11::ssize_t i = 0; i < a.shape(0); ++i) a(i) = markers[static_cast<size_t>(i)].*field;
  return out;
}

}  // namespace onetip::python
