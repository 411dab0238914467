#include "vision/triangulator.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/calib3d.hpp>

#include "core/error.hpp"

namespace onetip::vision {

namespace {

std::vector<cv::Point2d> undistortToIdealPixels(const std::vector<cv::Point2d>& pts,
                                                const cv::Matx33d& K,
                                                const cv::Vec<double, 5>& D) {
  std::vector<cv::Point2d> out;
  if (pts.empty()) return out;
  cv::undistortPoints(pts, out, K, D, cv::noArray(), K,
                      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-9));
  return out;
}

Eigen::Vector3d rayOf(const cv::Matx33d& K_inv, const cv::Point2d& p) {
  const cv::Vec3d r = K_inv * cv::Vec3d(p.x, p.y, 1.0);
  return {r[0], r[1], r[2]};
}

double pixelDistance(const cv::Matx33d& K, const Eigen::Vector3d& X, const cv::Point2d& p) {
  const cv::Vec3d x = K * cv::Vec3d(X.x() / X.z(), X.y() / X.z(), 1.0);
  return std::hypot(x[0] - p.x, x[1] - p.y);
}

}  // namespace

void TriangulatorOptions::validate() const {
  if (!(max_reprojection_px > 0.0))
    throw InputError("triangulator: max_reprojection_px: must be positive");
}

Triangulator::Triangulator(const StereoCalibration& calib, TriangulatorOptions options)
    : calib_(calib), options_(options) {
  calib_.validate();
  options_.validate();
  Kl_inv_ = calib_.K_left.inv();
  Kr_inv_ = calib_.K_right.inv();
  const cv::Vec3d& t = calib_.T;
  const cv::Matx33d tx(0, -t[2], t[1], t[2], 0, -t[0], -t[1], t[0], 0);
  F_ = Kr_inv_.t() * tx * calib_.R * Kl_inv_;
  for (int r = 0; r < 3; ++r) {
    T_[r] = t[r];
    for (int c = 0; c < 3; ++c) R_(r, c) = calib_.R(r, c);
  }
}

std::vector<TriangulatedPoint> Triangulator::triangulatePairs(
    const std::vector<cv::Point2d>& left, const std::vector<cv::Point2d>& right) const {
  if (left.size() != right.size())
    throw InputError("triangulator: left and right point lists differ in length");
  std::vector<TriangulatedPoint> out(left.size());
  if (left.empty()) return out;
  std::vector<cv::Point2d> l = undistortToIdealPixels(left, calib_.K_left, calib_.D_left);
  std::vector<cv::Point2d> r = undistortToIdealPixels(right, calib_.K_right, calib_.D_right);
  std::vector<cv::Point2d> l_ray = l, r_ray = r;  // the points the rays go through
  if (options_.method == TriangulationMethod::optimal) {
    cv::Mat l_fixed, r_fixed;
    cv::correctMatches(cv::Mat(F_), cv::Mat(l).reshape(2, 1), cv::Mat(r).reshape(2, 1), l_fixed,
                       r_fixed);
    for (size_t i = 0; i < l.size(); ++i) {
      l_ray[i] = l_fixed.at<cv::Point2d>(static_cast<int>(i));
      r_ray[i] = r_fixed.at<cv::Point2d>(static_cast<int>(i));
    }
  }
  const Eigen::Vector3d c_r = -R_.transpose() * T_;  // right camera centre in L
  for (size_t i = 0; i < l.size(); ++i) {
    // Shortest segment between X = s * a and X = c_r + u * b.
    const Eigen::Vector3d a = rayOf(Kl_inv_, l_ray[i]);
    const Eigen::Vector3d b = R_.transpose() * rayOf(Kr_inv_, r_ray[i]);
    const double aa = a.dot(a), bb = b.dot(b), ab = a.dot(b);
    const double ac = a.dot(c_r), bc = b.dot(c_r);
    const double den = aa * bb - ab * ab;
    TriangulatedPoint& p = out[i];
    if (!(std::abs(den) > 1e-15 * aa * bb)) continue;  // parallel rays: left invalid
    const double s = (ac * bb - ab * bc) / den;
    const double u = (ab * ac - aa * bc) / den;
    p.X_L = 0.5 * (s * a + c_r + u * b);
    const Eigen::Vector3d X_R = R_ * p.X_L + T_;
    p.in_front = p.X_L.z() > 0 && X_R.z() > 0;
    if (p.in_front)
      p.reprojection_px = std::max(pixelDistance(calib_.K_left, p.X_L, l[i]),
                                   pixelDistance(calib_.K_right, X_R, r[i]));
  }
  return out;
}

TriangulationResult Triangulator::triangulate(const ViewMarkers& left,
                                              const ViewMarkers& right) const {
  if (left.rows != right.rows || left.cols != right.cols)
    throw InputError("triangulator: the two views' marker grids differ in size");
  TriangulationResult result;
  result.markers = MarkerField(left.rows, left.cols);
  std::vector<int> ids;
  std::vector<cv::Point2d> l, r;
  for (int id = 0; id < left.size(); ++id)
    if (left.valid[static_cast<size_t>(id)] && right.valid[static_cast<size_t>(id)]) {
      ids.push_back(id);
      l.emplace_back(left.point[static_cast<size_t>(id)]);
      r.emplace_back(right.point[static_cast<size_t>(id)]);
    }
  result.matched = static_cast<int>(ids.size());
  const auto points = triangulatePairs(l, r);
  double sum_sq = 0.0;
  for (size_t i = 0; i < ids.size(); ++i) {
    const TriangulatedPoint& p = points[i];
    if (!p.in_front || p.reprojection_px > options_.max_reprojection_px) {
      ++result.rejected;
      continue;
    }
    result.markers.set(ids[i], p.X_L);
    const size_t k = static_cast<size_t>(ids[i]);
    const auto graded = [k](const ViewMarkers& m) { return k < m.confidence.size() ? m.confidence[k] : 1.0f; };
    result.markers.confidence[k] = std::min(graded(left), graded(right));
    sum_sq += p.reprojection_px * p.reprojection_px;
  }
  const int accepted = result.matched - result.rejected;
  if (accepted > 0) result.rms_reprojection_px = std::sqrt(sum_sq / accepted);
  return result;
}

}  // namespace onetip::vision
