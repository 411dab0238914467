// core/pattern.hpp — the checkerboard marker pattern (docs/reference.md).
//
// rows x cols inner corners, square_mm apart. Marker id = row * cols + col;
// in the left view row 0 is the top row of corners and col 0 the leftmost.
// marker_depth_mm: how deep the pattern lies below the pad's contact surface
// (the epidermis over the printed layer). A marker moves with the surface point
// above it, so a finger that tilts by R moves the markers by its motion
// conjugated with that offset (input/pose_accumulator.hpp); the pose needs it
// to report the finger's own motion. Optional in pattern files (default 0.3 mm,
// the simulated pad's; written only when it differs).
// The flat rest layout used by the simulator puts marker (row, col) at
// x = (col - (cols-1)/2) * square_mm, y = (row - (rows-1)/2) * square_mm.
#pragma once

#include <string>

namespace onetip {

struct MarkerPattern {
  int rows = 17;
  int cols = 17;
  double square_mm = 1.2;
  static constexpr double kMaxMarkerDepthMm = 10;
  double marker_depth_mm = 0.3;  // [0, kMaxMarkerDepthMm] mm below the contact surface

  int count() const noexcept { return rows * cols; }
  int id(int row, int col) const noexcept { return row * cols + col; }
  int rowOf(int id) const noexcept { return id / cols; }
  int colOf(int id) const noexcept { return id % cols; }

  // Throws InputError naming the bad field.
  void validate() const;
};

// Reads a pattern file (YAML or JSON, keys rows, cols, square_mm and the optional
// marker_depth_mm; core/config_file.hpp);
// throws InputError naming the file, line and key.
MarkerPattern loadPattern(const std::string& path);
// Writes the pattern file atomically; throws InputError when it cannot.
void savePattern(const MarkerPattern& pattern, const std::string& path);

}  // namespace onetip
