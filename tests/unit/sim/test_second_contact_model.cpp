// The simulator's second contact model (PadOptions::contact_model =
// foundation) against independent predictions, and the seeded random
// scenarios that use both models.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "sim/contact_kernel.hpp"
#include "sim/contact_model.hpp"
#include "sim/random_scenario.hpp"
#include "sim/simulator.hpp"

using namespace onetip;
using namespace onetip::sim;

namespace {

Eigen::Isometry3d tipAt(const PadOptions& pad, double x, double depth) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(x, 0, pad.pattern.marker_depth_mm - depth);
  return T;
}

PadOptions foundationPad() {
  PadOptions pad;
  pad.contact_model = ContactModelKind::foundation;
  pad.foundation_length_mm = 3.0;
  return pad;
}

}  // namespace

TEST(FoundationModel, OutsideTheContactTheSurfaceFollowsTheModifiedBesselDecay) {
  // A Pasternak foundation obeys (laplacian - 1/l^2) w = -p / G: outside an
  // axisymmetric loaded patch the decaying solution is w = A K0(r / l), so
  // w(r) / K0(r / l) is the same at every distance. The halfspace layer's
  // exp(-r/T)/r tail is not: that ratio drifts by far more.
  for (const ContactModelKind kind : {ContactModelKind::foundation, ContactModelKind::halfspace}) {
    PadOptions pad = foundationPad();
    pad.contact_model = kind;
    PadLattice lattice(pad);
    ContactModel model(lattice, {IndenterGeometry{IndenterShape::sphere, {6, 6, 6}}});
    model.reset({tipAt(pad, 0, -0.3)});
    model.advance({tipAt(pad, 0, 0.8)});
    double contact_radius = 0;
    for (int i : model.activeNodes()) contact_radius = std::max(contact_radius, lattice.surfaceRest(i).head<2>().norm());
    const double l = pad.foundation_length_mm;
    double lo = 1e9, hi = 0;
    for (int i = 0; i < lattice.nodeCount(); ++i) {
      const Eigen::Vector3d rest = lattice.surfaceRest(i);
      const double r = rest.head<2>().norm();
      if (std::abs(rest.y()) > 1e-9 || rest.x() < contact_radius + 2 * lattice.spacing() || r > 3 * l) continue;
      const double ratio = -model.displacement(i).z() / std::cyl_bessel_k(0.0, r / l);
      lo = std::min(lo, ratio);
      hi = std::max(hi, ratio);
    }
    ASSERT_GT(hi, 0);
    if (kind == ContactModelKind::foundation) EXPECT_LT(hi / lo, 1.1) << "ratio spread " << lo << " .. " << hi;
    else EXPECT_GT(hi / lo, 1.3) << "the halfspace tail should not follow K0";
  }
}

TEST(FoundationModel, GrossSlipCarriesTheKineticShareOfTheNormalLoad) {
  // Static/kinetic Coulomb: once the contact slides as a whole, the nodes that
  // keep sliding carry kinetic_ratio x mu p (a ratio of 1: plain Coulomb).
  for (const double kinetic : {1.0, 0.7}) {
    PadOptions pad = foundationPad();
    pad.kinetic_ratio = kinetic;
    PadLattice lattice(pad);
    ContactModel model(lattice, {IndenterGeometry{}});
    model.reset({tipAt(pad, 0, -0.3)});
    model.advance({tipAt(pad, 0, 1.0)});
    bool slid = false;
    for (int k = 1; k <= 160 && !slid; ++k) {
      model.advance({tipAt(pad, 0.025 * k, 1.0)});
      slid = model.state() == ContactState::slip;
    }
    ASSERT_TRUE(slid) << "never reached gross slip";
    model.advance({tipAt(pad, 0.025 * 161 + 0.2, 1.0)});  // keep sliding
    ASSERT_EQ(model.state(), ContactState::slip);
    // A node that was already sliding carries exactly kinetic x mu p; one that
    // only now breaks loose (a fresh node at the leading edge) carries mu p.
    int kinetic_nodes = 0, slipping = 0;
    for (int i : model.activeNodes()) {
      const NodeContact& node = model.node(i);
      ASSERT_TRUE(node.slip);
      const double share = node.q.norm() / (pad.friction * node.p);
      ++slipping;
      if (std::abs(share - kinetic) < 1e-6) ++kinetic_nodes;
      else EXPECT_NEAR(share, 1.0, 1e-6) << "node " << i;
    }
    EXPECT_GT(kinetic_nodes, 0.8 * slipping);
  }
}

TEST(FoundationModel, APressStillGivesTheCommandedDepthAndNothingElse) {
  // The ground truth is kinematic: whatever the physics, a pure press is dz only.
  Scenario sc;
  sc.name = "press";
  sc.pad = foundationPad();
  IndenterTrack tr;
  tr.keyframes = {{0.0, 0, 0, -0.3, 0, 0, 0}, {1.0, 0, 0, 2.0, 0, 0, 0}};
  sc.indenters = {tr};
  Simulator sim(sc);
  int contact = 0;
  while (!sim.done()) {
    const GroundTruthFrame& f = sim.next();
    if (!f.in_contact) continue;
    ++contact;
    for (double v : {f.input.dx, f.input.dy, f.input.yaw, f.input.pitch, f.input.roll}) EXPECT_NEAR(v, 0, 1e-9);
    EXPECT_EQ(f.state, ContactState::stick);
  }
  EXPECT_GT(contact, 20);
}

TEST(RandomScenario, OneSeedOneScenario) {
  const RandomScenario a = randomScenario(42), b = randomScenario(42), c = randomScenario(43);
  ASSERT_EQ(a.scenario.indenters.size(), b.scenario.indenters.size());
  for (size_t i = 0; i < a.scenario.indenters.size(); ++i) {
    const auto &ka = a.scenario.indenters[i].keyframes, &kb = b.scenario.indenters[i].keyframes;
    ASSERT_EQ(ka.size(), kb.size());
    for (size_t k = 0; k < ka.size(); ++k) {
      EXPECT_EQ(ka[k].t, kb[k].t);
      EXPECT_EQ(ka[k].x, kb[k].x);
      EXPECT_EQ(ka[k].pitch, kb[k].pitch);
    }
  }
  EXPECT_NE(a.conditions.fps, c.conditions.fps);
}

TEST(RandomScenario, ConditionsCoverTheirDocumentedRanges) {
  int models[2] = {0, 0}, two_fingers = 0;
  std::set<int> densities;
  std::set<std::string> indenters;
  for (unsigned seed = 1; seed <= 200; ++seed) {
    const RandomScenario rs = randomScenario(seed);
    const RandomConditions& c = rs.conditions;
    ++models[static_cast<int>(c.model)];
    densities.insert(c.markers);
    indenters.insert(c.indenter);
    two_fingers += c.two_fingers ? 1 : 0;
    EXPECT_GE(c.fps, 15);
    EXPECT_LE(c.fps, 240);
    EXPECT_GE(c.noise_grey, 1);
    EXPECT_LE(c.noise_grey, 6);
    EXPECT_NO_THROW(rs.scenario.pad.validate()) << "seed " << seed;
    for (const auto& tr : rs.scenario.indenters)
      for (const auto& k : tr.keyframes) {
        EXPECT_LE(std::abs(k.yaw), 15);
        EXPECT_LE(std::abs(k.pitch), 30);
        EXPECT_LE(std::abs(k.roll), 30);
        EXPECT_LE(k.depth, 3.0);
      }
  }
  EXPECT_GT(models[0], 60);
  EXPECT_GT(models[1], 60);
  EXPECT_EQ(densities.size(), 9u);  // 9, 11, ..., 25
  EXPECT_EQ(indenters.size(), 3u);
  EXPECT_GT(two_fingers, 5);
}

TEST(RandomScenario, PlaysThroughTheSimulator) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    Simulator sim(randomScenario(seed).scenario);
    int contact = 0;
    while (!sim.done()) contact += sim.next().in_contact ? 1 : 0;
    EXPECT_GT(contact, 0) << "seed " << seed << " never touched";
  }
}
