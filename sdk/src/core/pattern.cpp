#include "core/pattern.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/filestorage_io.hpp"

namespace onetip {

void MarkerPattern::validate() const {
  if (rows < 2 || rows > 1000) throw InputError("pattern: rows: must be between 2 and 1000");
  if (cols < 2 || cols > 1000) throw InputError("pattern: cols: must be between 2 and 1000");
  if (!(square_mm > 0.0) || !std::isfinite(square_mm))
    throw InputError("pattern: square_mm: must be a positive number");
}

MarkerPattern loadPattern(const std::string& path) {
  cv::FileStorage fs = openForReading(path);
  const cv::FileNode root = fs.root();
  MarkerPattern p;
  p.rows = readRequiredInt(root, "rows", path);
  p.cols = readRequiredInt(root, "cols", path);
  p.square_mm = readRequiredReal(root, "square_mm", path);
  try {
    p.validate();
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
  return p;
}

void savePattern(const MarkerPattern& pattern, const std::string& path) {
  pattern.validate();
  YamlWriter w;
  w.fs() << "rows" << pattern.rows << "cols" << pattern.cols << "square_mm" << pattern.square_mm;
  w.save(path);
}

}  // namespace onetip
