#include "pose/rigid_fit.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

namespace onetip::pose {

RigidFit fitRigidMotion(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to,
                        const std::vector<double>& weights) {
  RigidFit fit;
  const size_t n = from.size();
  if (n < 3 || to.size() != n || (!weights.empty() && weights.size() != n)) return fit;
  auto w = [&](size_t i) { return weights.empty() ? 1.0 : weights[i]; };
  double wsum = 0;
  Eigen::Vector3d ca = Eigen::Vector3d::Zero(), cb = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < n; ++i) {
    wsum += w(i);
    ca += w(i) * from[i];
    cb += w(i) * to[i];
  }
  if (!(wsum > 0)) return fit;
  ca /= wsum;
  cb /= wsum;
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  for (size_t i = 0; i < n; ++i) H += w(i) * (from[i] - ca) * (to[i] - cb).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Vector3d s = svd.singularValues();
  if (!(s[0] > 0) || s[1] < 1e-9 * s[0]) return fit;
  Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
  D(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0 ? -1.0 : 1.0;
  const Eigen::Matrix3d R = svd.matrixV() * D * svd.matrixU().transpose();
  fit.motion.linear() = R;
  fit.motion.translation() = cb - R * ca;
  double sq = 0;
  for (size_t i = 0; i < n; ++i) sq += w(i) * (fit.motion * from[i] - to[i]).squaredNorm();
  fit.rms_mm = std::sqrt(sq / wsum);
  fit.ok = fit.motion.matrix().allFinite();
  return fit;
}

RigidFit fitRigidMotionRobust(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to,
                              double scale_mm, int iterations) {
  RigidFit fit = fitRigidMotion(from, to);
  std::vector<double> w(from.size());
  for (int it = 0; it < iterations && fit.ok; ++it) {
    for (size_t i = 0; i < from.size(); ++i) {
      const double r = (fit.motion * from[i] - to[i]).norm() / scale_mm;
      w[i] = 1.0 / (1.0 + r * r);
    }
    const RigidFit next = fitRigidMotion(from, to, w);
    if (!next.ok) break;
    fit = next;
  }
  return fit;
}

TrimmedFit fitRigidMotionTrimmed(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to,
                                 const std::vector<Eigen::Vector3d>& relax, double scale_mm, double trim_mm,
                                 size_t min_kept) {
  TrimmedFit out;
  out.inlier.assign(from.size(), 1);
  std::vector<size_t> kept(from.size());
  for (size_t i = 0; i < kept.size(); ++i) kept[i] = i;
  std::vector<Eigen::Vector3d> a, b;
  for (;;) {
    a.clear();
    b.clear();
    for (size_t i : kept) {
      a.push_back(from[i]);
      b.push_back(to[i]);
    }
    out.fit = fitRigidMotion(a, b);
    if (!out.fit.ok || kept.size() <= std::max<size_t>(3, min_kept)) break;
    // While some residual exceeds trim_mm: the most lagging point if it lags
    // by more than a quarter of the largest residual, else the largest residual.
    long worst = -1, most_lagging = -1;
    double largest = trim_mm, largest_lag = 0;
    for (size_t k = 0; k < kept.size(); ++k) {
      const Eigen::Vector3d r = b[k] - out.fit.motion * a[k];
      if (r.norm() > largest) {
        largest = r.norm();
        worst = static_cast<long>(k);
      }
      const double lag = relax.empty() ? 0.0 : r.dot(relax[kept[k]]);
      if (lag > largest_lag) {
        largest_lag = lag;
        most_lagging = static_cast<long>(k);
      }
    }
    if (worst < 0) break;
    const long drop = most_lagging >= 0 && largest_lag > 0.25 * largest ? most_lagging : worst;
    out.inlier[kept[static_cast<size_t>(drop)]] = 0;
    kept.erase(kept.begin() + drop);
  }
  if (!out.fit.ok) return out;
  out.within_trim = true;
  for (size_t k = 0; k < a.size(); ++k) out.within_trim &= (b[k] - out.fit.motion * a[k]).norm() <= trim_mm;
  out.fit = fitRigidMotionRobust(a, b, scale_mm);
  return out;
}

RigidFit fitTranslation(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to) {
  RigidFit fit;
  if (from.empty() || to.size() != from.size()) return fit;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < from.size(); ++i) mean += to[i] - from[i];
  mean /= static_cast<double>(from.size());
  double sq = 0;
  for (size_t i = 0; i < from.size(); ++i) sq += (from[i] + mean - to[i]).squaredNorm();
  fit.motion.translation() = mean;
  fit.rms_mm = std::sqrt(sq / static_cast<double>(from.size()));
  fit.ok = mean.allFinite();
  return fit;
}

RigidFit fitRotationAboutZ(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to) {
  RigidFit fit;
  const size_t n = from.size();
  if (n < 2 || to.size() != n) return fit;
  Eigen::Vector3d ca = Eigen::Vector3d::Zero(), cb = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < n; ++i) {
    ca += from[i];
    cb += to[i];
  }
  ca /= static_cast<double>(n);
  cb /= static_cast<double>(n);
  double cross = 0, dot = 0;
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d a = (from[i] - ca).head<2>(), b = (to[i] - cb).head<2>();
    cross += a.x() * b.y() - a.y() * b.x();
    dot += a.dot(b);
  }
  if (!(std::hypot(cross, dot) > 0)) return fit;
  fit.motion.linear() = Eigen::AngleAxisd(std::atan2(cross, dot), Eigen::Vector3d::UnitZ()).toRotationMatrix();
  fit.motion.translation() = cb - fit.motion.linear() * ca;
  double sq = 0;
  for (size_t i = 0; i < n; ++i) sq += (fit.motion * from[i] - to[i]).squaredNorm();
  fit.rms_mm = std::sqrt(sq / static_cast<double>(n));
  fit.ok = fit.motion.matrix().allFinite();
  return fit;
}

Eigen::Vector2d planarSpread(const std::vector<Eigen::Vector3d>& points) { return planarExtent(points).spread; }

PlanarExtent planarExtent(const std::vector<Eigen::Vector3d>& points) {
  PlanarExtent out;
  if (points.size() < 2) return out;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : points) mean += p.head<2>();
  mean /= static_cast<double>(points.size());
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (const auto& p : points) cov += (p.head<2>() - mean) * (p.head<2>() - mean).transpose();
  cov /= static_cast<double>(points.size());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);  // ascending eigenvalues
  out.spread = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  out.major_axis = eig.eigenvectors().col(1);
  return out;
}

}  // namespace onetip::pose
