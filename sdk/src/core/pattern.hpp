// core/pattern.hpp — the checkerboard marker pattern (docs/reference.md).
//
// rows x cols inner corners, square_mm apart. Marker id = row * cols + col;
// in the left view row 0 is the top row of corners and col 0 the leftmost.
// The flat rest layout used by the simulator puts marker (row, col) at
// x = (col - (cols-1)/2) * square_mm, y = (row - (rows-1)/2) * square_mm.
#pragma once

#include <string>

namespace onetip {

struct MarkerPattern {
  int rows = 17;
  int cols = 17;
  double square_mm = 1.2;

  int count() const noexcept { return rows * cols; }
  int id(int row, int col) const noexcept { return row * cols + col; }
  int rowOf(int id) const noexcept { return id / cols; }
  int colOf(int id) const noexcept { return id % cols; }

  // Throws InputError naming the bad field.
  void validate() const;
};

// Reads a pattern file (YAML or JSON, keys rows, cols, square_mm; core/config_file.hpp);
// throws InputError naming the file, line and key.
MarkerPattern loadPattern(const std::string& path);
// Writes the pattern file atomically; throws InputError when it cannot.
void savePattern(const MarkerPattern& pattern, const std::string& path);

}  // namespace onetip
