#include "core/pattern.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/option_checks.hpp"
#include "core/config_file.hpp"
#include "core/filestorage_io.hpp"

namespace onetip {

void MarkerPattern::validate() const {
  if (rows < 2 || rows > 1000) throw InputError("pattern: rows: must be between 2 and 1000");
  if (cols < 2 || cols > 1000) throw InputError("pattern: cols: must be between 2 and 1000");
  if (!(square_mm > 0.0) || !std::isfinite(square_mm))
    throw InputError("pattern: square_mm: must be a positive number");
  requireInRange("pattern: marker_depth_mm", marker_depth_mm, 0, kMaxMarkerDepthMm, "mm");
}

MarkerPattern loadPattern(const std::string& path) {
  const ConfigNode root = ConfigNode::load(path);
  root.allowOnly({"rows", "cols", "square_mm", "marker_depth_mm"});
  MarkerPattern p;
  p.rows = root["rows"].integer(2, 1000);
  p.cols = root["cols"].integer(2, 1000);
  p.square_mm = root["square_mm"].real(1e-3, 1e4);
  p.marker_depth_mm = root.real("marker_depth_mm", MarkerPattern{}.marker_depth_mm, 0, MarkerPattern::kMaxMarkerDepthMm);
  return p;
}

void savePattern(const MarkerPattern& pattern, const std::string& path) {
  pattern.validate();
  YamlWriter w;
  w.fs() << "rows" << pattern.rows << "cols" << pattern.cols << "square_mm" << pattern.square_mm;
  // Only when it differs from the default: a file with the default pad keeps the
  // three keys of the documented format.
  if (pattern.marker_depth_mm != MarkerPattern{}.marker_depth_mm) w.fs() << "marker_depth_mm" << pattern.marker_depth_mm;
  w.save(path);
}

}  // namespace onetip
