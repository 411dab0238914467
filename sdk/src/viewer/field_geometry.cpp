#include "viewer/field_geometry.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace onetip::viewer {

namespace {
Eigen::Vector3f f(const Eigen::Vector3d& v) { return v.cast<float>(); }
}  // namespace

void FieldGeometryOptions::validate() const {
  if (!(exaggeration > 0 && exaggeration <= 20)) throw InputError("field view: exaggeration: must be in (0, 20]");
  if (!(arrow_gain > 0 && arrow_gain <= 100)) throw InputError("field view: arrow_gain: must be in (0, 100]");
  if (!(min_arrow_mm >= 0)) throw InputError("field view: min_arrow_mm: must be >= 0");
}

std::vector<Eigen::Vector3d> markerDisplacements(const MarkerField& now, const MarkerField& rest) {
  if (now.rows != rest.rows || now.cols != rest.cols)
    throw InputError("field view: current markers are " + std::to_string(now.rows) + "x" + std::to_string(now.cols) +
                     ", rest markers " + std::to_string(rest.rows) + "x" + std::to_string(rest.cols));
  std::vector<Eigen::Vector3d> u(static_cast<size_t>(rest.size()), Eigen::Vector3d::Zero());
  for (size_t i = 0; i < u.size(); ++i)
    if (now.valid[i] && rest.valid[i]) u[i] = now.position[i] - rest.position[i];
  return u;
}

MeshVertices deformationSurface(const MarkerField& now, const MarkerField& rest, const FieldGeometryOptions& options) {
  const std::vector<Eigen::Vector3d> u = markerDisplacements(now, rest);
  const int rows = rest.rows, cols = rest.cols;
  auto at = [&](int r, int c) {
    const auto i = static_cast<size_t>(r * cols + c);
    return Eigen::Vector3d(rest.position[i] + options.exaggeration * u[i]);
  };
  MeshVertices mesh;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const Eigen::Vector3d along_col = at(r, std::min(c + 1, cols - 1)) - at(r, std::max(c - 1, 0));
      const Eigen::Vector3d along_row = at(std::min(r + 1, rows - 1), c) - at(std::max(r - 1, 0), c);
      Eigen::Vector3d n = along_col.cross(along_row);
      n = n.norm() > 1e-12 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::UnitZ();
      const auto i = static_cast<size_t>(r * cols + c);
      mesh.add(f(at(r, c)), f(n), Rgba(0.8F, 0.8F, 0.8F, 1.0F), static_cast<float>(u[i].norm()));
    }
  auto ok = [&](int r, int c) {
    const auto i = static_cast<size_t>(r * cols + c);
    return rest.valid[i] && now.valid[i];
  };
  for (int r = 0; r + 1 < rows; ++r)
    for (int c = 0; c + 1 < cols; ++c) {
      if (!ok(r, c) || !ok(r, c + 1) || !ok(r + 1, c) || !ok(r + 1, c + 1)) continue;
      const auto a = static_cast<unsigned>(r * cols + c), b = a + 1, d = a + static_cast<unsigned>(cols), e = d + 1;
      mesh.indices.insert(mesh.indices.end(), {a, b, e, a, e, d});
    }
  return mesh;
}

PointVertices displacementArrows(const MarkerField& now, const MarkerField& rest, const FieldGeometryOptions& options) {
  const std::vector<Eigen::Vector3d> u = markerDisplacements(now, rest);
  const Rgba white(1.0F, 1.0F, 1.0F, 1.0F);
  PointVertices arrows;
  for (size_t i = 0; i < u.size(); ++i) {
    const Eigen::Vector3d tangential(u[i].x(), u[i].y(), 0.0);
    const double length = tangential.norm();
    if (!now.valid[i] || !rest.valid[i] || length <= options.min_arrow_mm) continue;
    const Eigen::Vector3d lift(0, 0, 0.05);  // just above the surface
    const Eigen::Vector3d start = rest.position[i] + options.exaggeration * u[i] + lift;
    const Eigen::Vector3d end = start + options.arrow_gain * tangential;
    const Eigen::Vector3d back = (start - end).normalized() * std::min(0.35, 0.4 * options.arrow_gain * length);
    const Eigen::Vector3d side(-back.y(), back.x(), 0.0);
    arrows.addLine(f(start), f(end), white);
    arrows.addLine(f(end), f(end + back + 0.5 * side), white);
    arrows.addLine(f(end), f(end + back - 0.5 * side), white);
  }
  return arrows;
}

Rgba stickColour() { return {0.15F, 0.85F, 0.25F, 1.0F}; }
Rgba slipColour() { return {0.95F, 0.15F, 0.15F, 1.0F}; }

PointVertices contactMap(const MarkerField& now, const MarkerField& rest, const contact::ContactField& field,
                         const pose::PoseStep& step) {
  const std::vector<Eigen::Vector3d> u = markerDisplacements(now, rest);
  PointVertices points;
  for (int id = 0; id < rest.size(); ++id) {
    const auto i = static_cast<size_t>(id);
    if (!rest.valid[i]) continue;
    Rgba colour(0.45F, 0.45F, 0.45F, 1.0F);
    const bool in_region = i < field.region_of.size() && field.region_of[i] >= 0;
    if (in_region) colour = Rgba(0.25F, 0.5F, 1.0F, 1.0F);
    if (i < step.labels.size()) switch (step.labels[i]) {
        case contact::MarkerLabel::stick: colour = stickColour(); break;
        case contact::MarkerLabel::slip: colour = slipColour(); break;
        case contact::MarkerLabel::detached: colour = Rgba(1.0F, 0.6F, 0.1F, 1.0F); break;
        case contact::MarkerLabel::outside: break;
      }
    const double press = std::clamp(-u[i].z() / 1.5, 0.0, 1.0);
    const Eigen::Vector3f at(static_cast<float>(rest.position[i].x()), static_cast<float>(rest.position[i].y()), 0.0F);
    points.add(at, colour, static_cast<float>(4.0 + 10.0 * press), !now.valid[i]);
  }
  return points;
}

}  // namespace onetip::viewer
