// pose/stick_slip_solver.hpp — the paper's stick/slip-aware least squares
// (Eq. 13-15), solved with Ceres.
//
// The finger's motion from frame k-1 to k, dT = T_k * T_{k-1}^-1, is found by
//   min  1/n_stick sum_i |dT(p_i) - p'_i|^2  +  1/n_slip sum_j (n_j . (dT(q_j) - q'_j))^2
// where p_i -> p'_i are stick markers (three residuals each: they move with the
// finger) and q_j -> q'_j slip markers (one residual along the contact normal
// n_j: a slipping point slides tangentially but stays on the finger's
// surface). Eq. 14-15 written with (R^k, t^k) are exactly these residuals with
// dT = (R^k R^{k-1,-1}, t^k - R^k R^{k-1,-1} t^{k-1}). Points in S, mm.
// Parameterisation: dT(x) = exp([w]x)(x - c) + c + v with the angle-axis
// vector w (radians, a proper rotation for every w) and v (mm); c is the mean
// of the `from` points, which decouples rotation and translation.
// Solvable when Eq. 16 holds: 3 n_stick + n_slip >= 6 and n_stick >= 1;
// otherwise ok = false and the initial motion is returned.
#pragma once

#include <Eigen/Geometry>
#include <vector>

namespace onetip::pose {

struct StickCorrespondence {
  Eigen::Vector3d from, to;
};

struct SlipCorrespondence {
  Eigen::Vector3d from, to;
  Eigen::Vector3d normal;  // unit contact normal at `to`
};

struct StickSlipSolverOptions {
  int max_iterations = 10;
  double function_tolerance = 1e-12;
  double parameter_tolerance = 1e-10;
  void validate() const;  // throws InputError naming the bad field
};

struct StickSlipSolution {
  bool ok = false;
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  int iterations = 0;
  double final_cost = 0;  // Ceres cost: half the weighted sum of squares
};

// True when Eq. 16 holds.
bool stickSlipSolvable(int n_stick, int n_slip);

// How well the residuals above fix the rotation (mm^2): the smallest
// eigenvalue of the rotation block of J^T J (unweighted, at dT = identity,
// about the stick markers' centroid) once the translation is eliminated
// (Schur complement). A rotation w moves a stick marker by w x r and a slip
// marker along its normal by w . (r x n), so the value is the least squared
// lever arm over all rotation axes once the translation has taken its share:
// about 0 when every marker lies on one line (the rotation about it is free),
// of the order of k s^2 when k markers act at s from every axis. 0 when there
// is no stick marker.
double stickSlipRotationInformation(const std::vector<StickCorrespondence>& stick,
                                    const std::vector<SlipCorrespondence>& slip);

StickSlipSolution solveStickSlipMotion(const std::vector<StickCorrespondence>& stick,
                                       const std::vector<SlipCorrespondence>& slip,
                                       const Eigen::Isometry3d& initial, const StickSlipSolverOptions& options = {});

}  // namespace onetip::pose
