#include "sim/camera_rig.hpp"

#include <cmath>

#include "core/error.hpp"

namespace onetip::sim {

bool VirtualCamera::project(const Eigen::Vector3d& X, Eigen::Vector2d& pixel) const {
  if (X.z() <= 1e-9) return false;
  const double x = X.x() / X.z(), y = X.y() / X.z();
  const double r2 = x * x + y * y;
  const double radial = 1 + D[0] * r2 + D[1] * r2 * r2 + D[4] * r2 * r2 * r2;
  const double xd = x * radial + 2 * D[2] * x * y + D[3] * (r2 + 2 * x * x);
  const double yd = y * radial + D[2] * (r2 + 2 * y * y) + 2 * D[3] * x * y;
  pixel = {K(0, 0) * xd + K(0, 1) * yd + K(0, 2), K(1, 1) * yd + K(1, 2)};
  return true;
}

void CameraRigOptions::validate() const {
  if (view_width < 16 || view_width > 8192) throw InputError("camera: view_width: out of range 16..8192");
  if (view_height < 16 || view_height > 8192)
    throw InputError("camera: view_height: out of range 16..8192");
  if (!(focal_px > 1)) throw InputError("camera: focal_px: must be > 1");
  if (!(distance_mm > 1)) throw InputError("camera: distance_mm: must be > 1");
  if (!(baseline_mm > 0)) throw InputError("camera: baseline_mm: must be > 0");
  for (double k : {k1, k2, p1, p2, k3})
    if (!std::isfinite(k) || std::abs(k) > 1.0) throw InputError("camera: distortion coefficient out of range [-1, 1]");
}

namespace {
VirtualCamera aimAtOrigin(const Eigen::Vector3d& centre, const CameraRigOptions& o, bool flip) {
  const Eigen::Vector3d z = (-centre).normalized();
  Eigen::Vector3d x = Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitX().dot(z) * z;
  x.normalize();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix3d R;
  R.row(0) = x.transpose();
  R.row(1) = y.transpose();
  R.row(2) = z.transpose();
  VirtualCamera cam;
  cam.camera_from_sensor.linear() = R;
  cam.camera_from_sensor.translation() = -R * centre;
  cam.K = cv::Matx33d(o.focal_px, 0, (o.view_width - 1) / 2.0, 0, o.focal_px, (o.view_height - 1) / 2.0,
                      0, 0, 1);
  cam.D = cv::Vec<double, 5>(o.k1, o.k2, o.p1, o.p2, o.k3);
  cam.flip = flip;
  return cam;
}
}  // namespace

CameraRig CameraRig::fromOptions(const CameraRigOptions& o) {
  o.validate();
  CameraRig rig;
  rig.view_width = o.view_width;
  rig.view_height = o.view_height;
  rig.left = aimAtOrigin({-o.baseline_mm / 2, 0, -o.distance_mm}, o, o.flip_left);
  rig.right = aimAtOrigin({o.baseline_mm / 2, 0, -o.distance_mm}, o, o.flip_right);
  return rig;
}

StereoCalibration CameraRig::calibration() const {
  StereoCalibration c;
  c.image_width = 2 * view_width;
  c.image_height = view_height;
  c.split_x = view_width;
  c.flip_left = left.flip;
  c.flip_right = right.flip;
  c.K_left = left.K;
  c.K_right = right.K;
  c.D_left = left.D;
  c.D_right = right.D;
  const Eigen::Isometry3d right_from_left = right.camera_from_sensor * left.camera_from_sensor.inverse();
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 3; ++k) c.R(r, k) = right_from_left.linear()(r, k);
    c.T[r] = right_from_left.translation()[r];
  }
  return c;
}

}  // namespace onetip::sim
