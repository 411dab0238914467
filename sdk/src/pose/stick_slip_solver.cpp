#include "pose/stick_slip_solver.hpp"

#include <ceres/ceres.h>
#include <ceres/rotation.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "core/error.hpp"

namespace onetip::pose {

void StickSlipSolverOptions::validate() const {
  if (max_iterations < 1) throw InputError("stick/slip solver options: max_iterations must be at least 1");
  if (!(function_tolerance > 0)) throw InputError("stick/slip solver options: function_tolerance must be positive");
  if (!(parameter_tolerance > 0)) throw InputError("stick/slip solver options: parameter_tolerance must be positive");
}

bool stickSlipSolvable(int n_stick, int n_slip) { return 3 * n_stick + n_slip >= 6 && n_stick >= 1; }

double stickSlipRotationInformation(const std::vector<StickCorrespondence>& stick,
                                    const std::vector<SlipCorrespondence>& slip) {
  if (stick.empty()) return 0;
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& s : stick) c += s.from;
  c /= static_cast<double>(stick.size());
  // Rows d(residual)/d(v, w): stick [I, -[r]x] (3 rows), slip [n^T, (r x n)^T] (1 row).
  Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
  for (const auto& s : stick) {
    Eigen::Matrix<double, 3, 6> j;
    const Eigen::Vector3d r = s.from - c;
    j.leftCols<3>().setIdentity();
    j.rightCols<3>() << 0, r.z(), -r.y(), -r.z(), 0, r.x(), r.y(), -r.x(), 0;  // d(w x r)/dw = -[r]x
    normal += j.transpose() * j;
  }
  for (const auto& s : slip) {
    Eigen::Matrix<double, 1, 6> j;
    j << s.normal.transpose(), (s.from - c).cross(s.normal).transpose();
    normal += j.transpose() * j;
  }
  const Eigen::Matrix3d schur = normal.bottomRightCorner<3, 3>() - normal.bottomLeftCorner<3, 3>() *
                                                                      normal.topLeftCorner<3, 3>().inverse() *
                                                                      normal.topRightCorner<3, 3>();
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(schur).eigenvalues().minCoeff();
}

namespace {

// dT(x) = exp([w]) (x - c) + c + v for a point given relative to c.
template <typename T>
void moved(const T* w, const T* v, const Eigen::Vector3d& x_rel, const Eigen::Vector3d& c, T* out) {
  const T p[3] = {T(x_rel.x()), T(x_rel.y()), T(x_rel.z())};
  ceres::AngleAxisRotatePoint(w, p, out);
  for (int k = 0; k < 3; ++k) out[k] += T(c[k]) + v[k];
}

struct StickResidual {
  Eigen::Vector3d from_rel, to, centre;
  double scale;
  template <typename T>
  bool operator()(const T* w, const T* v, T* r) const {
    T m[3];
    moved(w, v, from_rel, centre, m);
    for (int k = 0; k < 3; ++k) r[k] = T(scale) * (m[k] - T(to[k]));
    return true;
  }
};

struct SlipResidual {
  Eigen::Vector3d from_rel, to, centre, normal;
  double scale;
  template <typename T>
  bool operator()(const T* w, const T* v, T* r) const {
    T m[3];
    moved(w, v, from_rel, centre, m);
    r[0] = T(0);
    for (int k = 0; k < 3; ++k) r[0] += T(scale * normal[k]) * (m[k] - T(to[k]));
    return true;
  }
};

}  // namespace

StickSlipSolution solveStickSlipMotion(const std::vector<StickCorrespondence>& stick,
                                       const std::vector<SlipCorrespondence>& slip,
                                       const Eigen::Isometry3d& initial, const StickSlipSolverOptions& options) {
  StickSlipSolution out;
  out.motion = initial;
  const int ns = static_cast<int>(stick.size()), nl = static_cast<int>(slip.size());
  if (!stickSlipSolvable(ns, nl)) return out;

  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& s : stick) centre += s.from;
  for (const auto& s : slip) centre += s.from;
  centre /= static_cast<double>(ns + nl);
  // Initial parameters: initial(x) = R x + t = R (x - c) + c + v  =>  v = R c + t - c.
  const Eigen::AngleAxisd aa(initial.linear());
  double w[3], v[3];
  const Eigen::Vector3d w0 = aa.angle() * aa.axis();
  const Eigen::Vector3d v0 = initial.linear() * centre + initial.translation() - centre;
  for (int k = 0; k < 3; ++k) {
    w[k] = w0[k];
    v[k] = v0[k];
  }

  ceres::Problem::Options problem_options;
  problem_options.enable_fast_removal = false;
  ceres::Problem problem(problem_options);
  const double stick_scale = std::sqrt(1.0 / ns);
  const double slip_scale = nl > 0 ? std::sqrt(1.0 / nl) : 0.0;
  for (const auto& s : stick)
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<StickResidual, 3, 3, 3>(
                                 new StickResidual{s.from - centre, s.to, centre, stick_scale}),
                             nullptr, w, v);
  for (const auto& s : slip)
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<SlipResidual, 1, 3, 3>(
                                 new SlipResidual{s.from - centre, s.to, centre, s.normal, slip_scale}),
                             nullptr, w, v);

  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = options.max_iterations;
  so.function_tolerance = options.function_tolerance;
  so.parameter_tolerance = options.parameter_tolerance;
  so.num_threads = 1;
  so.logging_type = ceres::SILENT;
  so.minimizer_progress_to_stdout = false;
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);

  const Eigen::Vector3d wv(w[0], w[1], w[2]), vv(v[0], v[1], v[2]);
  if (!summary.IsSolutionUsable() || !wv.allFinite() || !vv.allFinite()) return out;
  const double angle = wv.norm();
  const Eigen::Matrix3d R =
      angle > 0 ? Eigen::AngleAxisd(angle, wv / angle).toRotationMatrix() : Eigen::Matrix3d::Identity();
  out.motion.linear() = R;
  out.motion.translation() = centre + vv - R * centre;
  out.iterations = static_cast<int>(summary.iterations.size());
  out.final_cost = summary.final_cost;
  out.ok = true;
  return out;
}

}  // namespace onetip::pose
