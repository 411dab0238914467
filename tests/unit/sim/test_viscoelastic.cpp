// The viscoelastic layer (sim/viscoelastic_layer.hpp) against the standard
// linear solid's closed forms, with the elastic run of the same scenario (the
// layer off) as the independent instantaneous response u_e:
//   held press (load stepped at t = 0):  u(t) = u_e (1 + c (1 - exp(-t / tau_c)))
//   after release at t_m:                u(t) = v(t_m) exp(-(t - t_m) / tau_c)
// with c = r / (1 - r), tau_c = tau / (1 - r) for E(t) = E0 (1 - r (1 - exp(-t / tau))).
// The scene steps the load over 1 ms (keyframes must be increasing); the
// model holds each frame's load over the whole step before it, so the
// continuous answer may differ by the creep of 1 ms: c (1 - exp(-1 ms / tau_c)) |u_e|.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/simulator.hpp"
#include "world_test_scenes.hpp"

using namespace onetip;
using namespace onetip::sim;

namespace {
constexpr double kRelaxation = 0.3, kTau = 0.3;  // r, tau (s)
constexpr double kRelease = 3.0;                 // s
constexpr double kRamp = 0.001;                  // s

Scenario creepScene(double relaxation) {
  Scenario sc = testsupport::sphereScene({{0, -1}, {kRamp, 1.0}, {kRelease, 1.0}, {kRelease + kRamp, -1}, {5.0, -1}});
  sc.world.viscoelastic.relaxation = relaxation;
  sc.world.viscoelastic.time_s = kTau;
  return sc;
}

Eigen::Vector3d displacement(const GroundTruthFrame& f, const MarkerField& rest, int id) {
  return f.markers.position[static_cast<size_t>(id)] - rest.position[static_cast<size_t>(id)];
}
}  // namespace

TEST(Viscoelastic, HeldPressCreepsAndReleasedGelRecoversAsTheStandardLinearSolid) {
  const double c = kRelaxation / (1 - kRelaxation), tau_c = kTau / (1 - kRelaxation);
  const double ramp_tol = c * (1 - std::exp(-kRamp / tau_c));
  Simulator elastic(creepScene(0)), gel(creepScene(kRelaxation));
  const MarkerField& rest = elastic.restMarkers();
  std::vector<Eigen::Vector3d> held_delayed;  // v(t_m) per marker at the last held frame
  std::vector<double> held_elastic;           // |u_e(t_m)|
  double t_m = 0, largest_recovering = 0, largest_ratio = 0;
  int checked = 0, recovering_frames = 0;
  while (!elastic.done()) {
    const GroundTruthFrame& e = elastic.next();
    const GroundTruthFrame& g = gel.next();
    if (e.t <= kRelease) {
      held_delayed.clear();
      held_elastic.clear();
      for (int id = 0; id < rest.size(); ++id) {
        const Eigen::Vector3d ue = displacement(e, rest, id), u = displacement(g, rest, id);
        held_delayed.push_back(u - ue);
        held_elastic.push_back(ue.norm());
        if (ue.norm() < 0.05) continue;
        const double creep = 1 + c * (1 - std::exp(-e.t / tau_c));
        EXPECT_LE((u - creep * ue).norm(), ramp_tol * ue.norm() + 1e-9) << "t " << e.t << " marker " << id;
        largest_ratio = std::max(largest_ratio, u.norm() / ue.norm());
        ++checked;
      }
      EXPECT_EQ(g.in_contact, e.in_contact) << "t " << e.t;
      t_m = e.t;
      continue;
    }
    // Released: the elastic pad is at rest at once, the gel recovers.
    double largest = 0;
    for (int id = 0; id < rest.size(); ++id) {
      EXPECT_LE(displacement(e, rest, id).norm(), 1e-9);
      const Eigen::Vector3d expected = held_delayed[static_cast<size_t>(id)] * std::exp(-(e.t - t_m) / tau_c);
      const Eigen::Vector3d u = displacement(g, rest, id);
      EXPECT_LE((u - expected).norm(), ramp_tol * held_elastic[static_cast<size_t>(id)] + 1e-9)
          << "t " << e.t << " marker " << id;
      largest = std::max(largest, u.norm());
    }
    largest_recovering = std::max(largest_recovering, largest);
    // The truth follows the finger, not the gel (ground_truth.hpp).
    EXPECT_FALSE(g.in_contact) << "t " << e.t << ": the finger has lifted, the gel is only recovering";
    EXPECT_EQ(g.indenter_nodes.at(0), 0);
    if (largest > 0.1) ++recovering_frames;
  }
  EXPECT_GT(checked, 1000);
  // Held for 7 retardation times: the creep reached the relaxed compliance 1 / (1 - r) = 1.43.
  EXPECT_NEAR(largest_ratio, 1 / (1 - kRelaxation), 0.01);
  // Recovery is slow: above the SDK's 0.1 mm contact threshold for frames after lift-off.
  EXPECT_GT(largest_recovering, 0.3);
  EXPECT_GE(recovering_frames, 10);
}

TEST(Viscoelastic, PressDuringRecoveryIsInContactFromItsFirstTouch) {
  Scenario sc = creepScene(kRelaxation);
  // A second press 0.2 s after the release, while the gel is still well deformed.
  sc.indenters[0].keyframes = {{0, 0, 0, -1}, {kRamp, 0, 0, 1.0}, {1.0, 0, 0, 1.0}, {1.0 + kRamp, 0, 0, -1},
                               {1.2, 0, 0, -1}, {1.2 + kRamp, 0, 0, 0.8}, {2.0, 0, 0, 0.8}};
  Simulator elastic([&] { Scenario s = sc; s.world.viscoelastic.relaxation = 0; return s; }()), gel(sc);
  while (!elastic.done()) {
    const GroundTruthFrame& e = elastic.next();
    const GroundTruthFrame& g = gel.next();
    EXPECT_EQ(g.in_contact, e.in_contact) << "t " << e.t;
    EXPECT_NEAR(g.input.dz, e.input.dz, 1e-12) << "t " << e.t << ": the truth is the finger's motion";
  }
}

TEST(Viscoelastic, OptionsRefuseOutOfRangeValues) {
  ViscoelasticOptions v;
  v.relaxation = 0.7;
  EXPECT_THROW(v.validate(), std::exception);
  v.relaxation = 0.2;
  v.time_s = 0.001;
  EXPECT_THROW(v.validate(), std::exception);
  v.time_s = 2;
  EXPECT_NO_THROW(v.validate());
}
