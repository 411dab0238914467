// sim/camera_rig.hpp — the simulated virtual binocular camera (the mirror pair).
//
// Two pinhole cameras with OpenCV lens distortion (k1 k2 p1 p2 k3) look at the
// pad from inside (from -z in S). Each renders a view_width x view_height
// grey half-image; the halves sit side by side in one frame (left first),
// each optionally mirrored horizontally (mirror optics), exactly as the
// calibration file of docs/reference.md describes. camera_from_sensor maps a
// point in the sensor frame S (mm) to the camera frame (x right, y down,
// z forward, mm).
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "core/calibration.hpp"

namespace onetip::sim {

struct VirtualCamera {
  cv::Matx33d K = cv::Matx33d::eye();
  cv::Vec<double, 5> D{0, 0, 0, 0, 0};
  Eigen::Isometry3d camera_from_sensor = Eigen::Isometry3d::Identity();
  bool flip = false;

  // Projects a camera-frame point to distorted pixel coordinates of the view
  // (after the flip, i.e. the pinhole view). Returns false behind the camera.
  bool project(const Eigen::Vector3d& X_cam, Eigen::Vector2d& pixel) const;
};

struct CameraRigOptions {
  int view_width = 960;          // pixels per half; the frame is 2 * view_width wide
  int view_height = 1080;
  double focal_px = 1000.0;      // fx = fy
  double distance_mm = 28.0;     // camera centres below the marker plane (along -S.z)
  double baseline_mm = 24.0;     // between the two virtual camera centres, along S.x
  double k1 = -0.12, k2 = 0.04, p1 = 0.0004, p2 = -0.0003, k3 = 0.0;
  bool flip_left = true;         // mirror optics: each half arrives mirrored
  bool flip_right = true;
  void validate() const;         // throws InputError naming the bad field
};

struct CameraRig {
  VirtualCamera left, right;
  int view_width = 960, view_height = 1080;

  // Both cameras aim at the origin of S from (-+baseline/2, 0, -distance),
  // image x along +S.x and image y along +S.y (so rows grow with S.y).
  static CameraRig fromOptions(const CameraRigOptions& o);

  // The exact calibration of this rig in the file format of docs/reference.md.
  StereoCalibration calibration() const;
  // X_L = left_from_sensor * X_S (the ground-truth S of the SDK is then
  // recovered from the rest markers, not from this).
  const Eigen::Isometry3d& leftFromSensor() const { return left.camera_from_sensor; }
};

}  // namespace onetip::sim
