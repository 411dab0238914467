#include "pose/contact_cap.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "contact/footprint_centre.hpp"

namespace onetip::pose {

namespace {

// Symmetric 2 x 2 with its eigenvalues clipped below at `floor`.
Eigen::Matrix2d clippedBelow(const Eigen::Matrix2d& h, double floor) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(h);
  const Eigen::Vector2d l = eig.eigenvalues().cwiseMax(floor);
  return eig.eigenvectors() * l.asDiagonal() * eig.eigenvectors().transpose();
}

}  // namespace

ContactCap fitContactCap(const std::vector<Eigen::Vector3d>& p, const std::vector<double>& n, double cut_mm) {
  ContactCap cap;
  const size_t count = p.size();
  if (count < 4 || n.size() != count) return cap;
  cap.centre = contact::footprintCentre(p, n, cut_mm);
  const bool full = count >= 6;
  const int unknowns = full ? 6 : 4;
  Eigen::MatrixXd A(static_cast<Eigen::Index>(count), unknowns);
  Eigen::VectorXd z(static_cast<Eigen::Index>(count));
  Eigen::Matrix2d moment = Eigen::Matrix2d::Zero();
  double weight = 0;
  for (size_t i = 0; i < count; ++i) {
    const Eigen::Vector2d x = p[i].head<2>() - cap.centre.head<2>();
    const auto r = static_cast<Eigen::Index>(i);
    if (full) A.row(r) << 1, x.x(), x.y(), 0.5 * x.x() * x.x(), x.x() * x.y(), 0.5 * x.y() * x.y();
    else A.row(r) << 1, x.x(), x.y(), 0.5 * x.squaredNorm();
    z[r] = p[i].z();
    const double w = std::max(0.0, n[i] - cut_mm);
    moment += w * x * x.transpose();
    weight += w;
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
  if (qr.rank() < unknowns) return cap;
  const Eigen::VectorXd c = qr.solve(z);
  Eigen::Matrix2d h;
  if (full) h << c[3], c[4], c[4], c[5];
  else h = c[3] * Eigen::Matrix2d::Identity();
  if (!h.allFinite()) return cap;
  cap.curvature = clippedBelow(h, 1.0 / kMaxCapRadiusMm);
  if (weight > 0) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(moment / weight);
    const Eigen::Vector2d major = eig.eigenvectors().col(1);
    cap.axis_rad = std::atan2(major.y(), major.x());
    cap.anisotropy = eig.eigenvalues()[0] > 0 ? eig.eigenvalues()[1] / eig.eigenvalues()[0] : 1.0;
    cap.minor_extent_mm = std::sqrt(std::max(0.0, eig.eigenvalues()[0]));
  }
  cap.markers = static_cast<int>(count);
  cap.full = full;
  cap.valid = true;
  return cap;
}

Eigen::Vector2d rollingShift(const ContactCap& cap, const Eigen::Vector3d& w) {
  if (!cap.valid) return Eigen::Vector2d::Zero();
  return cap.curvature.inverse() * Eigen::Vector2d(w.y(), -w.x());
}

}  // namespace onetip::pose
