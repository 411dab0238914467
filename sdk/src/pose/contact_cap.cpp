#include "pose/contact_cap.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "contact/contact_field.hpp"
#include "contact/footprint_centre.hpp"
#include "core/marker_field.hpp"

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
  for (size_t i = 0; i < count; ++i) {
    const Eigen::Vector2d x = p[i].head<2>() - cap.centre.head<2>();
    const auto r = static_cast<Eigen::Index>(i);
    if (full) A.row(r) << 1, x.x(), x.y(), 0.5 * x.x() * x.x(), x.x() * x.y(), 0.5 * x.y() * x.y();
    else A.row(r) << 1, x.x(), x.y(), 0.5 * x.squaredNorm();
    z[r] = p[i].z();
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
  if (qr.rank() < unknowns) return cap;
  const Eigen::VectorXd c = qr.solve(z);
  Eigen::Matrix2d h;
  if (full) h << c[3], c[4], c[4], c[5];
  else h = c[3] * Eigen::Matrix2d::Identity();
  if (!h.allFinite()) return cap;
  cap.curvature = clippedBelow(h, 1.0 / kMaxCapRadiusMm);
  cap.valid = true;
  return cap;
}

Eigen::Vector2d rollingShift(const ContactCap& cap, const Eigen::Vector3d& w) {
  if (!cap.valid) return Eigen::Vector2d::Zero();
  return cap.curvature.inverse() * Eigen::Vector2d(w.y(), -w.x());
}

ContactCap fitContactCap(const contact::ContactField& field, const std::vector<int>& members, const MarkerField& now) {
  std::vector<Eigen::Vector3d> p;
  std::vector<double> n;
  for (int id : members) {
    const size_t i = static_cast<size_t>(id);
    if (!now.valid[i] || !field.valid[i]) continue;
    p.push_back(now.position[i]);
    n.push_back(-field.displacement[i].z());
  }
  return fitContactCap(p, n, field.cutOf(members));
}

}  // namespace onetip::pose
