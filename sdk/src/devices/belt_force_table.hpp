// devices/belt_force_table.hpp — the angle-force calibration of the 2-DoF
// belt device (thesis Sec. 2.1.2), from the human-as-force-sensor procedure.
//
// The user feels the motor at its maximum torque (100 % force, its angle
// theta_max) and sets, by feel, the angles of 50 %, then 25 % and 75 % of that
// force. The table holds those points (force fraction f_k, angle theta_k) with
// the origin (0, 0) implied; between points the map is piecewise linear:
//   theta(f) = theta_k + (f - f_k) (theta_{k+1} - theta_k) / (f_{k+1} - f_k)
// (the thesis finds two lines with a break near 60 % of theta_max at 25 % of
// the force). force(theta) is its inverse. f is clamped to [0, 1].
// File: CSV with header `force_percent,angle_deg`, one row per point, force
// strictly increasing in (0, 100] and ending at 100, angles strictly
// increasing and positive; at least three rows (25, 50, 75, 100 usually).
#pragma once

#include <string>
#include <vector>

namespace onetip::devices {

struct AngleForcePoint {
  double force_fraction = 0.0;  // 0..1
  double angle_deg = 0.0;
};

class BeltForceTable {
 public:
  // Throws InputError naming `where` and the bad row.
  static BeltForceTable fromPoints(std::vector<AngleForcePoint> points, const std::string& where = "force table");
  static BeltForceTable load(const std::string& csv_path);
  void save(const std::string& csv_path) const;

  double angleFor(double force_fraction) const;
  double forceFor(double angle_deg) const;
  double maxAngle() const { return points_.back().angle_deg; }
  const std::vector<AngleForcePoint>& points() const noexcept { return points_; }  // with the origin

 private:
  std::vector<AngleForcePoint> points_;
};

}  // namespace onetip::devices
