#include "core/sensor_frame.hpp"

#include <Eigen/SVD>

#include "core/error.hpp"

namespace onetip {

SensorFrame SensorFrame::fromRestMarkers(const MarkerField& rest) {
  const int n = rest.validCount();
  if (n < 3) throw InputError("sensor frame: fewer than 3 rest markers were measured");
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (int i = 0; i < rest.size(); ++i)
    if (rest.valid[i]) centroid += rest.position[i];
  centroid /= n;

  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (int i = 0; i < rest.size(); ++i)
    if (rest.valid[i]) {
      const Eigen::Vector3d d = rest.position[i] - centroid;
      scatter += d * d.transpose();
    }
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(scatter, Eigen::ComputeFullU);
  if (svd.singularValues()[1] <= 1e-12 * std::max(1.0, svd.singularValues()[0]))
    throw InputError("sensor frame: the rest markers are collinear");
  Eigen::Vector3d z = svd.matrixU().col(2);
  if (z.dot(centroid) < 0) z = -z;  // away from the camera at the origin of L

  // Mean direction of increasing column index, from every valid horizontal link.
  Eigen::Vector3d along_cols = Eigen::Vector3d::Zero();
  for (int r = 0; r < rest.rows; ++r)
    for (int c = 0; c + 1 < rest.cols; ++c) {
      const int a = r * rest.cols + c;
      if (rest.valid[a] && rest.valid[a + 1]) along_cols += rest.position[a + 1] - rest.position[a];
    }
  Eigen::Vector3d x = along_cols - along_cols.dot(z) * z;
  if (x.norm() < 1e-9) throw InputError("sensor frame: no two neighbouring rest markers in a row");
  x.normalize();
  const Eigen::Vector3d y = z.cross(x);

  Eigen::Matrix3d S_R_L;
  S_R_L.row(0) = x.transpose();
  S_R_L.row(1) = y.transpose();
  S_R_L.row(2) = z.transpose();
  Eigen::Isometry3d S_from_L = Eigen::Isometry3d::Identity();
  S_from_L.linear() = S_R_L;
  S_from_L.translation() = -S_R_L * centroid;
  return SensorFrame(S_from_L);
}

MarkerField SensorFrame::toSensor(const MarkerField& in_L) const {
  MarkerField out = in_L;
  for (int i = 0; i < out.size(); ++i)
    if (out.valid[i]) out.position[i] = S_from_L_ * in_L.position[i];
  return out;
}

}  // namespace onetip
