// pose/weighted_increment.hpp — the finger's motion over one frame from
// weighted evidence: the paper's Eq. 13-15 with stick weights, the footprint
// and a motion prior in one least-squares problem.
//
// The increment dT (S, mm) acts as dT(q) = R (q - c) + c + v about the point
// c (the finger's reference point), so rotation and translation decouple.
// It minimises, with every residual divided by its standard deviation,
//   (1/n) sum_i w_i |dT(a_i) - p_i|^2 / s_i^2           stick: anchor a_i (carried
//                                                       to frame k-1) onto p_i now
// + (1/n) sum_i (1 - w_i) (n_i . (dT(b_i) - p_i))^2 / u_i^2   slip: a sliding marker stays on
//                                                       the finger's surface (normal n_i)
// + |P_xy (dT(f) - g)|^2 / s_f^2                       footprint: carried by the finger
// + |theta - theta_p|^2 / s_turn^2 + |v - v_p|^2 / s_slide^2   prior: the motion expected
//                                                       (theta_p = v_p = 0: held)
// (n the number of markers: their residuals are largely the marker layer's
// shared deformation, so together they count as one marker at their spread,
// as in pose/pose_uncertainty.hpp). With w_i in {0, 1} and no footprint this is
// the paper's Eq. 13-15; with every w_i = 1 it is Kabsch (Eq. 1); with every
// w_i = 0 the footprint carries the slide (Sec. III-D) while the normal
// residuals keep the depth and tilt. Solved by Gauss-Newton on the left
// perturbation dT <- (exp(dtheta), dv) dT, a 6 x 6 system per iteration.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <vector>

namespace onetip::pose {

struct WeightedMarker {
  Eigen::Vector3d anchor;              // a_i carried to frame k-1 (S, mm)
  Eigen::Vector3d before;              // b_i measured at frame k-1 (S, mm)
  Eigen::Vector3d now;                 // p_i measured (S, mm)
  Eigen::Vector3d normal;              // unit contact normal at p_i (S); zero: no slip residual
  double weight = 1;                   // w_i in [0, 1]
  double sd_mm = 0.001;                // s_i: per-axis sd of a sticking marker's residual
  double on_surface = 1;               // v_i in [0, 1]: the slip residual's weight is (1 - w_i) v_i (a marker the
                                       // finger does not touch is not on its surface)
  Eigen::Vector3d from_rest{0, 0, 0};  // unit direction of the marker's displacement from rest (zero: none)
  double surface_sd_mm = 0;            // u_i: sd of the sliding residual along the normal (0: s_i); it
                                       // can carry the slide's model error on top of the noise
};

// The residuals at a solution, each in units of its marker's sd: e_i = (dT(a_i) - p_i) / s_i (|e_i|^2 is
// chi-square with 3 degrees of freedom for a sticking marker) and (n_i . (dT(b_i) - p_i)) / u_i.
struct WeightedResiduals {
  std::vector<Eigen::Vector3d> stick;
  std::vector<double> normal;
};

struct FootprintEvidence {
  Eigen::Vector3d carried;  // f: where the finger carried the footprint to at frame k-1 (S, mm)
  Eigen::Vector3d seen;     // g: where it is now (S, mm)
  double sd_mm = 1;         // s_f per axis (x, y)
};

struct WeightedIncrementProblem {
  Eigen::Vector3d centre{0, 0, 0};  // c (S, mm)
  std::vector<WeightedMarker> markers;
  std::optional<FootprintEvidence> footprint;
  double prior_turn_sd_rad = 0.1;  // s_turn
  double prior_slide_sd_mm = 1;    // s_slide
  // The prior's expected increment: theta_p, the turn as an axis times its angle (S, rad), and v_p, the
  // move of c (S, mm). Zero holds the motion; a motion prior with a rate expects the last increment again.
  Eigen::Vector3d prior_turn_rad{0, 0, 0};
  Eigen::Vector3d prior_slide_mm{0, 0, 0};
};

// Gauss-Newton from `initial`; the residuals at the result in `residuals` when given.
Eigen::Isometry3d solveWeightedIncrement(const WeightedIncrementProblem& problem, const Eigen::Isometry3d& initial,
                                         WeightedResiduals* residuals = nullptr, int iterations = 3);

// Whether the marker lies further from rest than the finger carries it, beyond the noise (see stickWeight).
bool leadsTheFinger(const WeightedMarker& marker, const Eigen::Vector3d& residual);

// A marker's stick weight at GNC's mu (mu = infinity: the truncated cost itself) from its residual e_i.
// The gel relaxes towards rest relative to the finger and never outruns it (the finger is a solid it cannot
// pass; friction drags the skin, it does not push it ahead): a marker found further from rest than the
// finger carries it, beyond the noise (-e_i . from_rest > sqrt(chi2_1(0.99))), cannot be slipping and must
// be explained: weight 1. Otherwise the truncated least-squares weight.
double stickWeight(const WeightedMarker& marker, const Eigen::Vector3d& residual, double cbar2, double mu);

// The objective the weights stand for (every residual in units of its sd): each marker pays
//   min(|e_i|^2, cbar^2 + min(nu_i^2, cbar_1^2))   (|e_i|^2 alone for a marker that leads, see stickWeight)
// divided by n: it sticks, or it slips on the finger's surface, or it is off the surface, whichever costs
// least; plus the footprint and the prior as above. cbar^2 = chi2_3(0.99) (kStickChi2) and cbar_1^2 =
// chi2_1(0.99) (kSurfaceChi2): a marker that sticks or slides is taken for something else once in a hundred.
constexpr double kStickChi2 = 11.34;
constexpr double kSurfaceChi2 = 6.63;
double truncatedCost(const WeightedIncrementProblem& problem, const Eigen::Isometry3d& increment);

// Truncated least squares by reweighting from the problem's current weights: each round every marker takes
// the weights of its cheapest case above at the last solution, until none changes. Converges to the
// minimum nearest its start; the weights are left in the problem's markers (0 or 1).
Eigen::Isometry3d solveByReweighting(WeightedIncrementProblem& problem, const Eigen::Isometry3d& initial);

// Graduated non-convexity (pose/truncated_least_squares.hpp) from every marker sticking, then reweighting:
// the weights are left in the problem's markers, 0 or 1.
Eigen::Isometry3d solveByGraduatedNonConvexity(WeightedIncrementProblem& problem, const Eigen::Isometry3d& initial);

}  // namespace onetip::pose
