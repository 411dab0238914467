// core/marker_field.hpp — 3-D marker positions on the pattern grid.
//
// A dense array indexed by marker id (row * cols + col) with a validity flag,
// so grid neighbours are index arithmetic. Positions in millimetres, in the
// frame the producer states (left camera L from the triangulator, S after
// SensorFrame::toSensor). confidence: per marker, 0..1, how sure the producer
// is of that measurement (the vision front end: the lower of the two views'
// grid-tracker confidences, vision/grid_tracker.hpp); 1 where it does not
// grade, meaningful only where valid.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/pattern.hpp"

namespace onetip {

struct MarkerField {
  int rows = 0;
  int cols = 0;
  std::vector<Eigen::Vector3d> position;  // size rows * cols
  std::vector<std::uint8_t> valid;        // 1 where position holds a measurement
  std::vector<float> confidence;          // 0..1 per marker (1: not graded)

  MarkerField() = default;
  MarkerField(int rows_, int cols_)
      : rows(rows_), cols(cols_), position(static_cast<size_t>(rows_ * cols_), Eigen::Vector3d::Zero()),
        valid(static_cast<size_t>(rows_ * cols_), 0), confidence(static_cast<size_t>(rows_ * cols_), 1.0f) {}
  explicit MarkerField(const MarkerPattern& p) : MarkerField(p.rows, p.cols) {}

  int size() const noexcept { return rows * cols; }
  int validCount() const noexcept {
    int n = 0;
    for (auto v : valid) n += v ? 1 : 0;
    return n;
  }
  void set(int id, const Eigen::Vector3d& p) {
    position[static_cast<size_t>(id)] = p;
    valid[static_cast<size_t>(id)] = 1;
  }
};

}  // namespace onetip
