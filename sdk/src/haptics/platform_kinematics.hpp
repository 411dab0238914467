// haptics/platform_kinematics.hpp — the 3-DoF cable-driven fingertip display
// of the papers, reduced to simple, documented geometry.
//
// Device frame D (mm): x to the finger's right, y along the finger towards
// the tip, z up through the finger towards the nail. The fingertip's pad
// touches the plane z = 0 from above at rest. Three servos on the static
// platform above the nail each wind a cable on a pulley of radius r_p; the
// cables run (near) vertically down to the vertices of the mobile platform,
// and springs around them push the platform away from the finger to its rest
// height z = -gap.
//   vertices (x_i, y_i) on a circle of radius r_b around the platform centre:
//     motor 1 (front, towards the fingertip):  angle  90 deg
//     motor 2 (rear right):                    angle -30 deg
//     motor 3 (rear left):                     angle 210 deg
//   servo angle theta_i in [30, 195] deg (clamped); rest at 30 deg;
//   vertex height  h_i = -gap + r_p * (theta_i - 30 deg) [rad]   (winding lifts it)
// The platform is the plane through (x_i, y_i, h_i): z = z_c + a x + b y with
// z_c = mean(h_i) (the vertices' centroid is the origin), unit normal
// n = (-a, -b, 1) / |(-a, -b, 1)| pointing up into the finger. Reported as
// n = Ry(roll) * Rx(pitch) * e_z:  pitch = -asin(n_y), roll = atan2(n_x, n_z)
// (degrees; pitch > 0 lifts the front, roll > 0 lifts the left side).
// Neglected: the small lateral motion of the vertices when tilted, cable
// stretch, spring and fingertip compliance (the platform goes where the cables
// put it), and servo dynamics (these are servo_response.hpp, for replays over
// time).
// Defaults: r_p = 1.5 mm (4.3 mm of travel over 165 deg), r_b = 7 mm
// (about 22 deg of tilt), gap = 1.5 mm.
#pragma once

#include <Eigen/Core>
#include <array>

namespace onetip::haptics {

constexpr double kServoMinDeg = 30.0;
constexpr double kServoMaxDeg = 195.0;

struct PlatformGeometry {
  double pulley_radius_mm = 1.5;
  double vertex_radius_mm = 7.0;
  double rest_gap_mm = 1.5;
  void validate() const;  // throws InputError naming the bad field
};

// A flat contact plate: the plane through `point` with unit `normal` pointing
// from the plate into the finger; finger points q with normal.(q - point) < 0
// are behind its face.
struct ContactPlane {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

struct PlatformPose {
  double z_mm = 0.0;        // height of the platform centre (z_c)
  double roll_deg = 0.0;
  double pitch_deg = 0.0;
  ContactPlane plane;       // in D
};

// Servo angles clamped to [30, 195] deg.
std::array<double, 3> clampServoAngles(const std::array<double, 3>& degrees);

class PlatformKinematics {
 public:
  explicit PlatformKinematics(const PlatformGeometry& geometry = {});
  // Forward kinematics from servo angles in degrees (clamped first).
  PlatformPose forward(const std::array<double, 3>& degrees) const;
  // Platform vertex i in D for the given angles (for drawing and tests).
  Eigen::Vector3d vertex(int i, const std::array<double, 3>& degrees) const;
  const PlatformGeometry& geometry() const noexcept { return geometry_; }

 private:
  PlatformGeometry geometry_;
  std::array<Eigen::Vector2d, 3> xy_;
};

}  // namespace onetip::haptics
