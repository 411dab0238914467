#include "sim/raster_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "sim/raster_checker.hpp"

namespace onetip::sim {

namespace {

constexpr int kSubpixelBits = 8;
constexpr std::int64_t kSubpixel = std::int64_t{1} << kSubpixelBits;
constexpr double kMaxPixelCoordinate = 1 << 16;  // keeps edge-function products far inside int64

struct ScreenVertex {
  std::int64_t X = 0, Y = 0;  // pixel coordinates * kSubpixel
  double z = 0;               // camera-frame depth, mm
  bool valid = false;
};

std::int64_t floorDiv(std::int64_t a, std::int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
std::int64_t ceilDiv(std::int64_t a, std::int64_t b) { return -floorDiv(-a, b); }

std::vector<ScreenVertex> toFixedPoint(const std::vector<ProjectedVertex>& projected) {
  std::vector<ScreenVertex> out(projected.size());
  for (size_t i = 0; i < out.size(); ++i) {
    const ProjectedVertex& p = projected[i];
    if (p.valid)
      out[i] = {std::llround(p.pixel.x() * kSubpixel), std::llround(p.pixel.y() * kSubpixel), p.depth, true};
  }
  return out;
}

struct TexturedVertex {
  const ScreenVertex* s;
  double u, v;
};

// An edge function cross(b - a, P - a) >= 0 inside, with the fill-rule bias
// folded in so that "inside" is simply value >= 0.
struct EdgeFunction {
  std::int64_t step_x, step_y, value;  // value at the first pixel of the bounding box
  EdgeFunction(const ScreenVertex& a, const ScreenVertex& b, std::int64_t px, std::int64_t py) {
    const std::int64_t dx = b.X - a.X, dy = b.Y - a.Y;
    const bool owns_boundary = dy > 0 || (dy == 0 && dx < 0);  // exactly one of two opposite edges
    step_x = -dy * kSubpixel;
    step_y = dx * kSubpixel;
    value = dx * (py - a.Y) - dy * (px - a.X) - (owns_boundary ? 0 : 1);
  }
};

class TriangleRasterizer {
 public:
  TriangleRasterizer(const FilteredChecker& checker, ViewTarget& target, double min_footprint)
      : checker_(checker), target_(target), min_footprint_(min_footprint) {}

  void draw(TexturedVertex a, TexturedVertex b, TexturedVertex c) const {
    std::int64_t area2 = (b.s->X - a.s->X) * (c.s->Y - a.s->Y) - (b.s->Y - a.s->Y) * (c.s->X - a.s->X);
    if (area2 == 0) return;
    if (area2 < 0) {
      std::swap(b, c);
      area2 = -area2;
    }
    const int width = target_.grey.cols, height = target_.grey.rows;
    const auto [min_x, max_x] = std::minmax({a.s->X, b.s->X, c.s->X});
    const auto [min_y, max_y] = std::minmax({a.s->Y, b.s->Y, c.s->Y});
    const int x0 = static_cast<int>(std::max<std::int64_t>(ceilDiv(min_x, kSubpixel), 0));
    const int x1 = static_cast<int>(std::min<std::int64_t>(floorDiv(max_x, kSubpixel), width - 1));
    const int y0 = static_cast<int>(std::max<std::int64_t>(ceilDiv(min_y, kSubpixel), 0));
    const int y1 = static_cast<int>(std::min<std::int64_t>(floorDiv(max_y, kSubpixel), height - 1));
    if (x0 > x1 || y0 > y1) return;

    const std::int64_t px = std::int64_t{x0} * kSubpixel, py = std::int64_t{y0} * kSubpixel;
    const EdgeFunction ea(*b.s, *c.s, px, py), eb(*c.s, *a.s, px, py), ec(*a.s, *b.s, px, py);

    // Affine attribute planes in pixel units: f(x, y) = f_a + fx * (x - xa) + fy * (y - ya).
    const double inv_area = double(kSubpixel * kSubpixel) / double(area2);
    const double bx = double(b.s->X - a.s->X) / kSubpixel, by = double(b.s->Y - a.s->Y) / kSubpixel;
    const double cx = double(c.s->X - a.s->X) / kSubpixel, cy = double(c.s->Y - a.s->Y) / kSubpixel;
    auto gradient = [&](double fa, double fb, double fc) {
      return cv::Vec2d(((fb - fa) * cy - (fc - fa) * by) * inv_area, ((fc - fa) * bx - (fb - fa) * cx) * inv_area);
    };
    const cv::Vec2d gu = gradient(a.u, b.u, c.u), gv = gradient(a.v, b.v, c.v),
                    gz = gradient(a.s->z, b.s->z, c.s->z);
    const double ox = x0 - double(a.s->X) / kSubpixel, oy = y0 - double(a.s->Y) / kSubpixel;
    const double u00 = a.u + gu[0] * ox + gu[1] * oy, v00 = a.v + gv[0] * ox + gv[1] * oy,
                 z00 = a.s->z + gz[0] * ox + gz[1] * oy;
    const Footprint footprint(std::max(0.5 * (std::abs(gu[0]) + std::abs(gu[1])), min_footprint_),
                              std::max(0.5 * (std::abs(gv[0]) + std::abs(gv[1])), min_footprint_));

    const auto [u_lo, u_hi] = std::minmax({a.u, b.u, c.u});
    const auto [v_lo, v_hi] = std::minmax({a.v, b.v, c.v});
    const auto u_at = [&](double dx, double dy) { return u00 + gu[0] * dx + gu[1] * dy; };
    const auto v_at = [&](double dx, double dy) { return v00 + gv[0] * dx + gv[1] * dy; };
    double flat_grey = 0;
    switch (checker_.classify(u_lo, u_hi, v_lo, v_hi, footprint, flat_grey)) {
      case FilteredChecker::Region::kUniform:
        fill(x0, x1, y0, y1, ea, eb, ec, z00, gz, [grey = static_cast<float>(flat_grey)](double, double) { return grey; });
        break;
      case FilteredChecker::Region::kBoardInterior:
        fill(x0, x1, y0, y1, ea, eb, ec, z00, gz, [&](double dx, double dy) {
          return static_cast<float>(checker_.shadeBoard(u_at(dx, dy), v_at(dx, dy), footprint));
        });
        break;
      case FilteredChecker::Region::kGeneral:
        fill(x0, x1, y0, y1, ea, eb, ec, z00, gz, [&](double dx, double dy) {
          return static_cast<float>(checker_.shade(u_at(dx, dy), v_at(dx, dy), footprint));
        });
        break;
    }
  }

 private:
  // Visits the pixels of the bounding box inside all three edges, depth-tests
  // them and stores shade(dx, dy) (offsets from the box's first pixel).
  template <typename Shade>
  void fill(int x0, int x1, int y0, int y1, const EdgeFunction& ea, const EdgeFunction& eb, const EdgeFunction& ec,
            double z00, const cv::Vec2d& gz, Shade shade) const {
    for (int y = y0; y <= y1; ++y) {
      const int row = y - y0;
      std::int64_t fa = ea.value + row * ea.step_y, fb = eb.value + row * eb.step_y, fc = ec.value + row * ec.step_y;
      float* grey = target_.grey.ptr<float>(y);
      float* depth = target_.depth.ptr<float>(y);
      for (int x = x0; x <= x1; ++x, fa += ea.step_x, fb += eb.step_x, fc += ec.step_x) {
        if ((fa | fb | fc) < 0) continue;
        const double dx = x - x0;
        const auto z = static_cast<float>(z00 + gz[0] * dx + gz[1] * row);
        if (!(z < depth[x])) continue;
        depth[x] = z;
        grey[x] = shade(dx, double(row));
      }
    }
  }

  const FilteredChecker& checker_;
  ViewTarget& target_;
  double min_footprint_;
};

}  // namespace

std::vector<ProjectedVertex> projectSheet(const CheckerSheet& sheet, const VirtualCamera& cam,
                                          double accepted_radius2) {
  std::vector<ProjectedVertex> out(sheet.position.size());
  const Eigen::Matrix3d R = cam.camera_from_sensor.linear();
  const Eigen::Vector3d t = cam.camera_from_sensor.translation();
  for (size_t i = 0; i < out.size(); ++i) {
    const Eigen::Vector3d X = R * sheet.position[i] + t;
    if (!(X.z() > 1e-6)) continue;
    const double x = X.x() / X.z(), y = X.y() / X.z();
    if (!(x * x + y * y <= accepted_radius2)) continue;
    Eigen::Vector2d p;
    if (!cam.project(X, p) || !(std::abs(p.x()) < kMaxPixelCoordinate && std::abs(p.y()) < kMaxPixelCoordinate))
      continue;
    out[i] = {p, X.z(), true};
  }
  return out;
}

void validateSheet(const CheckerSheet& s) {
  if (s.nu < 2 || s.nv < 2) throw InputError("sheet: nu, nv: need at least 2 x 2 vertices");
  if (s.position.size() != static_cast<size_t>(s.nu) * static_cast<size_t>(s.nv))
    throw InputError("sheet: position: expected nu * nv vertices");
  if (!(s.spacing_mm > 0)) throw InputError("sheet: spacing_mm: must be > 0");
  if (!(s.texture.square_mm > 0)) throw InputError("sheet: texture.square_mm: must be > 0");
  if (s.texture.rows < 1 || s.texture.cols < 1) throw InputError("sheet: texture.rows, cols: must be >= 1");
  if (!(s.texture.border_mm >= 0)) throw InputError("sheet: texture.border_mm: must be >= 0");
}

void ViewTarget::reset(cv::Size size, float empty_grey) {
  grey.create(size);
  grey.setTo(empty_grey);
  depth.create(size);
  depth.setTo(std::numeric_limits<float>::infinity());
}

cv::Mat1b ViewTarget::coverage() const {
  cv::Mat1b covered;
  cv::compare(depth, std::numeric_limits<float>::max(), covered, cv::CMP_LE);
  return covered;
}

double acceptedRadius2(const VirtualCamera& cam, cv::Size view) {
  const double cx = std::max(cam.K(0, 2), view.width - 1 - cam.K(0, 2)) / cam.K(0, 0);
  const double cy = std::max(cam.K(1, 2), view.height - 1 - cam.K(1, 2)) / cam.K(1, 1);
  const double limit = 4.0 * (cx * cx + cy * cy);
  // d(r * radial(r)) / dr = 1 + 3 k1 r^2 + 5 k2 r^4 + 7 k3 r^6 must stay positive.
  const double k1 = cam.D[0], k2 = cam.D[1], k3 = cam.D[4];
  constexpr int kSteps = 4000;
  for (int i = 1; i <= kSteps; ++i) {
    const double r2 = limit * i / kSteps;
    if (1 + 3 * k1 * r2 + 5 * k2 * r2 * r2 + 7 * k3 * r2 * r2 * r2 <= 0.05) return limit * (i - 1) / kSteps;
  }
  return limit;
}

void rasterizeSheet(const CheckerSheet& sheet, const VirtualCamera& cam, double accepted_radius2,
                    ViewTarget& target) {
  validateSheet(sheet);
  const std::vector<ScreenVertex> screen = toFixedPoint(projectSheet(sheet, cam, accepted_radius2));
  const FilteredChecker checker(sheet.texture);
  const TriangleRasterizer raster(checker, target, 1e-4 * sheet.texture.square_mm);
  for (int b = 0; b + 1 < sheet.nv; ++b) {
    const double v0 = sheet.v0 + b * sheet.spacing_mm, v1 = v0 + sheet.spacing_mm;
    for (int a = 0; a + 1 < sheet.nu; ++a) {
      const size_t i00 = static_cast<size_t>(b) * sheet.nu + a, i10 = i00 + 1, i01 = i00 + sheet.nu, i11 = i01 + 1;
      const double u0 = sheet.u0 + a * sheet.spacing_mm, u1 = u0 + sheet.spacing_mm;
      const TexturedVertex p00{&screen[i00], u0, v0}, p10{&screen[i10], u1, v0}, p01{&screen[i01], u0, v1},
          p11{&screen[i11], u1, v1};
      if (p00.s->valid && p10.s->valid && p11.s->valid) raster.draw(p00, p10, p11);
      if (p00.s->valid && p11.s->valid && p01.s->valid) raster.draw(p00, p11, p01);
    }
  }
}

}  // namespace onetip::sim
