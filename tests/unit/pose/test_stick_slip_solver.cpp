#include <gtest/gtest.h>

#include <random>

#include "core/rotation.hpp"
#include "pose/rigid_fit.hpp"
#include "pose/stick_slip_solver.hpp"

using namespace onetip;
using namespace onetip::pose;

namespace {

// Points on the finger's surface: a sphere of radius 8 mm touching z = 0 from above.
struct Contact {
  std::vector<StickCorrespondence> stick;
  std::vector<SlipCorrespondence> slip;
};

Contact makeContact(const Eigen::Isometry3d& T, int n_stick, int n_slip, double slide_mm) {
  const Eigen::Vector3d centre(0, 0, 8);
  Contact c;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-2.5, 2.5);
  for (int i = 0; i < n_stick + n_slip; ++i) {
    const double x = u(rng), y = u(rng);
    const Eigen::Vector3d p(x, y, 8 - std::sqrt(64 - x * x - y * y));
    const Eigen::Vector3d n = (centre - p).normalized();  // into the finger = out of the pad
    if (i < n_stick) {
      c.stick.push_back({p, T * p});
    } else {
      // Slides over the finger: moved with it, then along the surface tangent.
      Eigen::Vector3d tangent = n.cross(Eigen::Vector3d::UnitY()).normalized();
      const Eigen::Vector3d q = T * p + slide_mm * (T.linear() * tangent);
      c.slip.push_back({p, q, T.linear() * n});
    }
  }
  return c;
}

}  // namespace

TEST(StickSlipSolver, Equation16) {
  EXPECT_TRUE(stickSlipSolvable(2, 0));
  EXPECT_TRUE(stickSlipSolvable(1, 3));
  EXPECT_FALSE(stickSlipSolvable(1, 2));
  EXPECT_FALSE(stickSlipSolvable(0, 40));
}

TEST(StickSlipSolver, RecoversTheMotionDespiteSlippingMarkers) {
  const Eigen::Isometry3d T = rigidFromTranslationYawPitchRoll({0.05, -0.04, -0.03}, 0.02, -0.015, 0.01);
  const Contact c = makeContact(T, 8, 20, 0.05);
  const StickSlipSolution sol = solveStickSlipMotion(c.stick, c.slip, Eigen::Isometry3d::Identity());
  ASSERT_TRUE(sol.ok);
  EXPECT_LT(Eigen::AngleAxisd(sol.motion.linear().transpose() * T.linear()).angle(), 1e-4);
  EXPECT_LT((sol.motion.translation() - T.translation()).norm(), 1e-4);

  // The full-stick assumption (Eq. 1 over every marker) is biased by the slip.
  std::vector<Eigen::Vector3d> from, to;
  for (const auto& s : c.stick) { from.push_back(s.from); to.push_back(s.to); }
  for (const auto& s : c.slip) { from.push_back(s.from); to.push_back(s.to); }
  const RigidFit all = fitRigidMotion(from, to);
  EXPECT_GT((all.motion.translation() - T.translation()).norm(), 10 * (sol.motion.translation() - T.translation()).norm());
}

TEST(StickSlipSolver, RefusesWhenEquation16Fails) {
  const Eigen::Isometry3d T = rigidFromTranslationYawPitchRoll({0.05, 0, 0}, 0, 0, 0);
  const Contact c = makeContact(T, 0, 30, 0.05);
  const StickSlipSolution sol = solveStickSlipMotion(c.stick, c.slip, Eigen::Isometry3d::Identity());
  EXPECT_FALSE(sol.ok);
  EXPECT_TRUE(sol.motion.isApprox(Eigen::Isometry3d::Identity()));
}

// A line of stick markers along S.x fixes every rotation but the pitch about
// itself; slip markers off the line fix that one through their normal
// residuals. The information measure says so, and the solver then recovers a
// pitch the line alone cannot see.
TEST(StickSlipSolver, SlipMarkersOffAThinStickLineFixItsRotation) {
  const Eigen::Isometry3d T = rigidFromTranslationYawPitchRoll({0.01, 0.02, -0.01}, 0, 0.02, 0);  // pitch 1.1 deg
  const Eigen::Vector3d centre(0, 0, 8);
  const auto surface = [&](double x, double y) { return Eigen::Vector3d(x, y, 8 - std::sqrt(64 - x * x - y * y)); };
  std::vector<StickCorrespondence> line;
  for (double x : {-2.4, -1.2, 0.0, 1.2, 2.4}) line.push_back({surface(x, 0), T * surface(x, 0)});
  // Nearly free: the line only bends with the finger (z up to 0.36 mm), a weak lever.
  EXPECT_LT(stickSlipRotationInformation(line, {}), 0.1 * 1.2 * 1.2);

  std::vector<SlipCorrespondence> slip;
  for (double x : {-1.2, 1.2})
    for (double y : {-1.2, 1.2}) {
      const Eigen::Vector3d p = surface(x, y), n = (centre - p).normalized();
      const Eigen::Vector3d tangent = n.cross(Eigen::Vector3d::UnitX()).normalized();
      slip.push_back({p, T * p + 0.03 * (T.linear() * tangent), T.linear() * n});
    }
  const double info = stickSlipRotationInformation(line, slip);
  EXPECT_GT(info, 0.5 * 1.2 * 1.2);  // four markers act at 1.2 mm from the line
  EXPECT_LT(info, 4 * 1.2 * 1.2 + 1e-9);

  const StickSlipSolution sol = solveStickSlipMotion(line, slip, Eigen::Isometry3d::Identity());
  ASSERT_TRUE(sol.ok);
  EXPECT_LT(Eigen::AngleAxisd(sol.motion.linear().transpose() * T.linear()).angle(), 1e-4);
  EXPECT_LT((sol.motion.translation() - T.translation()).norm(), 1e-4);
  EXPECT_DOUBLE_EQ(stickSlipRotationInformation({}, slip), 0);
}
