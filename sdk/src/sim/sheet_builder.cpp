#include "sim/sheet_builder.hpp"

#include <algorithm>
#include <cmath>

namespace onetip::sim {

namespace {
// Catmull-Rom weights for the four samples around parameter s in [0, 1).
inline void catmullRom(double s, double w[4]) {
  const double s2 = s * s, s3 = s2 * s;
  w[0] = 0.5 * (-s3 + 2 * s2 - s);
  w[1] = 0.5 * (3 * s3 - 5 * s2 + 2);
  w[2] = 0.5 * (-3 * s3 + 4 * s2 + s);
  w[3] = 0.5 * (s3 - s2);
}

// Refines one axis of a grid stored as rows of `count` samples with `stride`.
std::vector<Eigen::Vector3d> refineAxis(const std::vector<Eigen::Vector3d>& in, int count, int lines, int factor,
                                        bool along_rows) {
  const int out_count = (count - 1) * factor + 1;
  std::vector<Eigen::Vector3d> out(static_cast<size_t>(out_count * lines));
  auto at = [&](int line, int k) -> const Eigen::Vector3d& {
    k = std::clamp(k, 0, count - 1);
    return along_rows ? in[static_cast<size_t>(line * count + k)] : in[static_cast<size_t>(k * lines + line)];
  };
  for (int line = 0; line < lines; ++line)
    for (int o = 0; o < out_count; ++o) {
      const int i = std::min(o / factor, count - 2);
      const double s = double(o - i * factor) / factor;
      double w[4];
      catmullRom(s, w);
      // Linear extrapolation past the ends keeps the edge intervals exact for affine data.
      const Eigen::Vector3d pm = i - 1 >= 0 ? at(line, i - 1) : Eigen::Vector3d(2 * at(line, i) - at(line, i + 1));
      const Eigen::Vector3d pp = i + 2 < count ? at(line, i + 2) : Eigen::Vector3d(2 * at(line, i + 1) - at(line, i));
      const Eigen::Vector3d v = w[0] * pm + w[1] * at(line, i) + w[2] * at(line, i + 1) + w[3] * pp;
      if (along_rows)
        out[static_cast<size_t>(line * out_count + o)] = v;
      else
        out[static_cast<size_t>(o * lines + line)] = v;
    }
  return out;
}
}  // namespace

CheckerSheet refineLattice(const std::vector<Eigen::Vector3d>& nodes, int nu, int nv, double u0, double v0,
                           double h, int factor, const CheckerTexture& texture) {
  CheckerSheet sheet;
  sheet.texture = texture;
  sheet.u0 = u0;
  sheet.v0 = v0;
  sheet.spacing_mm = h / factor;
  const std::vector<Eigen::Vector3d> rows_refined = refineAxis(nodes, nu, nv, factor, true);
  sheet.nu = (nu - 1) * factor + 1;
  sheet.position = refineAxis(rows_refined, nv, sheet.nu, factor, false);
  sheet.nv = (nv - 1) * factor + 1;
  return sheet;
}

CheckerSheet rigidBoard(const CheckerTexture& texture, const Eigen::Isometry3d& pose, double spacing_mm) {
  CheckerSheet sheet;
  sheet.texture = texture;
  const double sq = texture.square_mm;
  const double margin = sq + texture.border_mm + 0.5 * sq;
  sheet.u0 = -margin;
  sheet.v0 = -margin;
  sheet.spacing_mm = spacing_mm;
  sheet.nu = static_cast<int>(std::ceil(((texture.cols - 1) * sq + 2 * margin) / spacing_mm)) + 1;
  sheet.nv = static_cast<int>(std::ceil(((texture.rows - 1) * sq + 2 * margin) / spacing_mm)) + 1;
  const double cx = 0.5 * (texture.cols - 1) * sq, cy = 0.5 * (texture.rows - 1) * sq;
  sheet.position.resize(static_cast<size_t>(sheet.nu * sheet.nv));
  for (int b = 0; b < sheet.nv; ++b)
    for (int a = 0; a < sheet.nu; ++a)
      sheet.position[static_cast<size_t>(b * sheet.nu + a)] =
          pose * Eigen::Vector3d(sheet.u0 + a * spacing_mm - cx, sheet.v0 + b * spacing_mm - cy, 0);
  return sheet;
}

}  // namespace onetip::sim
