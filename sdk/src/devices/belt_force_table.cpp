#include "devices/belt_force_table.hpp"

#include <algorithm>
#include <cmath>

#include "core/csv_table.hpp"
#include "core/error.hpp"

namespace onetip::devices {
namespace {
// Piecewise-linear interpolation of y over increasing x, clamped at the ends.
double interpolate(const std::vector<AngleForcePoint>& p, double x, bool by_force) {
  auto xs = [&](size_t i) { return by_force ? p[i].force_fraction : p[i].angle_deg; };
  auto ys = [&](size_t i) { return by_force ? p[i].angle_deg : p[i].force_fraction; };
  if (!(x > xs(0))) return ys(0);
  for (size_t i = 1; i < p.size(); ++i)
    if (x <= xs(i)) return ys(i - 1) + (x - xs(i - 1)) * (ys(i) - ys(i - 1)) / (xs(i) - xs(i - 1));
  return ys(p.size() - 1);
}
}  // namespace

BeltForceTable BeltForceTable::fromPoints(std::vector<AngleForcePoint> points, const std::string& where) {
  if (!points.empty() && points.front().force_fraction == 0.0 && points.front().angle_deg == 0.0)
    points.erase(points.begin());
  if (points.size() < 3) throw InputError(where + ": needs at least three calibration points (e.g. 25, 50, 75, 100 %)");
  double f_prev = 0.0, a_prev = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    const std::string row = where + ": point " + std::to_string(i + 1);
    if (!(std::isfinite(p.force_fraction) && p.force_fraction > f_prev && p.force_fraction <= 1.0))
      throw InputError(row + ": force must increase strictly within (0, 100] %");
    if (!(std::isfinite(p.angle_deg) && p.angle_deg > a_prev && p.angle_deg <= 3600.0))
      throw InputError(row + ": angle must increase strictly (positive degrees)");
    f_prev = p.force_fraction;
    a_prev = p.angle_deg;
  }
  if (points.back().force_fraction != 1.0) throw InputError(where + ": the last point must be 100 % force");
  BeltForceTable t;
  t.points_.push_back({0.0, 0.0});
  t.points_.insert(t.points_.end(), points.begin(), points.end());
  return t;
}

BeltForceTable BeltForceTable::load(const std::string& csv_path) {
  const CsvTable table = readCsv(csv_path);
  const size_t force = table.column("force_percent", csv_path);
  const size_t angle = table.column("angle_deg", csv_path);
  std::vector<AngleForcePoint> points;
  for (size_t r = 0; r < table.rows.size(); ++r) {
    const std::string where = csv_path + ": line " + std::to_string(r + 2);
    points.push_back({parseNumber(table.rows[r][force], where + ", force_percent") / 100.0,
                      parseNumber(table.rows[r][angle], where + ", angle_deg")});
  }
  return fromPoints(std::move(points), csv_path);
}

void BeltForceTable::save(const std::string& csv_path) const {
  CsvWriter out(csv_path, {"force_percent", "angle_deg"});
  for (size_t i = 1; i < points_.size(); ++i)
    out.row({formatNumber(points_[i].force_fraction * 100.0), formatNumber(points_[i].angle_deg)});
  out.commit();
}

double BeltForceTable::angleFor(double force_fraction) const {
  return interpolate(points_, std::clamp(force_fraction, 0.0, 1.0), true);
}

double BeltForceTable::forceFor(double angle_deg) const { return interpolate(points_, angle_deg, false); }

}  // namespace onetip::devices
