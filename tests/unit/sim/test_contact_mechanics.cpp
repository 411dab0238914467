// Contact mechanics of the simulated pad against independent predictions:
// a pure press, stick nodes moving rigidly with the finger, and the
// Ciavarella-Jager prediction of incipient and gross slip under a slide.
#include <gtest/gtest.h>

#include "sim/contact_kernel.hpp"
#include "sim/contact_model.hpp"
#include "sim/scenario.hpp"
#include "sim/simulator.hpp"

using namespace onetip;
using namespace onetip::sim;

namespace {
Eigen::Isometry3d fingerAt(const PadOptions& pad, double x, double depth) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(x, 0, pad.pattern.marker_depth_mm - depth);  // tip of an upright ellipsoid
  return T;
}

Scenario pressScenario(double max_depth) {
  Scenario sc;
  sc.name = "press";
  IndenterTrack tr;
  tr.keyframes = {{0.0, 0, 0, -0.3, 0, 0, 0}, {1.0, 0, 0, max_depth, 0, 0, 0}};
  sc.indenters = {tr};
  return sc;
}
}  // namespace

TEST(ContactMechanics, PurePressGivesTheCommandedDepthAndNothingElse) {
  Simulator sim(pressScenario(3.5));
  double onset_depth = -1;
  int contact_frames = 0;
  while (!sim.done()) {
    const GroundTruthFrame& f = sim.next();
    const double depth = sim.scenario().indenters[0].at(f.t).depth;
    if (!f.in_contact) continue;
    if (onset_depth < 0) onset_depth = depth;
    ++contact_frames;
    EXPECT_NEAR(f.input.dz, depth - onset_depth, 1e-9) << "frame " << f.index;
    for (double v : {f.input.dx, f.input.dy, f.input.yaw, f.input.pitch, f.input.roll}) EXPECT_NEAR(v, 0, 1e-9);
    EXPECT_EQ(f.state, ContactState::stick);
    // the centre marker sits on the finger's tip: pushed down by exactly the depth
    const int centre = sim.pattern().id(8, 8);
    EXPECT_NEAR(f.markers.position[centre].z() - sim.restMarkers().position[centre].z(), -depth, 1e-9);
  }
  EXPECT_GT(contact_frames, 20);
  // the 0.1 mm deformation rule fires on the first frame pressed deeper than 0.1 mm
  const double depth_per_frame = 3.8 / sim.scenario().fps;
  EXPECT_GT(onset_depth, 0.1);
  EXPECT_LE(onset_depth, 0.1 + depth_per_frame + 1e-9);
}

TEST(ContactMechanics, OutsideTheContactTheSkinDipsLikeAnElasticLayer) {
  // Hertz-like behaviour: at the contact edge the surface is pressed about half
  // the approach (exactly half for a half-space), so the SDK's 50% rule finds the contact.
  PadOptions pad;
  PadLattice lattice(pad);
  ContactModel model(lattice, {IndenterGeometry{IndenterShape::sphere, {8, 8, 8}}});
  model.reset({fingerAt(pad, 0, -0.5)});
  model.advance({fingerAt(pad, 0, 1.0)});
  double edge_uz = 0;
  int edge_nodes = 0;
  for (int i : model.activeNodes()) {
    // nodes in contact with a neighbour out of contact are on the edge
    const int nu = lattice.nu();
    for (int nb : {i - 1, i + 1, i - nu, i + nu})
      if (!model.node(nb).contact) {
        edge_uz += -model.displacement(i).z();
        ++edge_nodes;
        break;
      }
  }
  ASSERT_GT(edge_nodes, 4);
  edge_uz /= edge_nodes;
  EXPECT_GT(edge_uz, 0.3);   // clearly more than a Winkler bed's ~0
  EXPECT_LT(edge_uz, 0.85);  // but less than the full approach
}

TEST(ContactMechanics, StickNodesMoveRigidlyWithTheFinger) {
  PadOptions pad;
  PadLattice lattice(pad);
  ContactModel model(lattice, {IndenterGeometry{}});
  model.reset({fingerAt(pad, 0, -0.3)});
  model.advance({fingerAt(pad, 0, 1.0)});
  std::vector<Eigen::Vector3d> before(static_cast<size_t>(lattice.nodeCount()));
  for (int i : model.activeNodes()) before[static_cast<size_t>(i)] = model.displacement(i);
  // a small rigid motion: 0.05 mm sideways and a 1 degree twist about the tip
  Eigen::Isometry3d T = fingerAt(pad, 0.05, 1.0);
  T.linear() = Eigen::AngleAxisd(1.0 * M_PI / 180, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Isometry3d motion = T * fingerAt(pad, 0, 1.0).inverse();
  model.advance({T});
  int checked = 0;
  for (int i : model.activeNodes()) {
    if (model.node(i).slip || before[static_cast<size_t>(i)].isZero()) continue;
    const Eigen::Vector3d p0 = lattice.surfaceRest(i) + before[static_cast<size_t>(i)];
    const Eigen::Vector3d p1 = lattice.surfaceRest(i) + model.displacement(i);
    EXPECT_LT((p1 - motion * p0).norm(), 1e-6) << "node " << i;
    ++checked;
  }
  EXPECT_GT(checked, 10);
}

TEST(ContactMechanics, SlowSlideShrinksTheStickRegionThenSlipsWherePredicted) {
  PadOptions pad;
  PadLattice lattice(pad);
  ContactModel model(lattice, {IndenterGeometry{}});
  const double depth = 1.0;
  model.reset({fingerAt(pad, 0, -0.3)});
  model.advance({fingerAt(pad, 0, depth)});
  const double predicted_gross_slip = tangentialComplianceRatio(pad.contact_model) * pad.friction * depth;  // 1.5 mm
  std::vector<int> previous_stick;
  for (int i : model.activeNodes()) previous_stick.push_back(i);
  double gross_slip_at = -1;
  for (int k = 1; k <= 100 && gross_slip_at < 0; ++k) {
    const double s = 0.025 * k;
    model.advance({fingerAt(pad, s, depth)});
    std::vector<int> stick;
    for (int i : model.activeNodes())
      if (!model.node(i).slip) stick.push_back(i);
    // monotone: a node that slips does not stick again while the finger keeps sliding,
    // apart from fresh nodes entering at the leading edge
    for (int i : stick) {
      const bool was_stick = std::find(previous_stick.begin(), previous_stick.end(), i) != previous_stick.end();
      const bool fresh = lattice.surfaceRest(i).x() > s;  // ahead of the tip: just came into contact
      EXPECT_TRUE(was_stick || fresh) << "node " << i << " re-stuck at s = " << s;
    }
    if (model.state() == ContactState::slip) gross_slip_at = s;
    previous_stick = stick;
  }
  ASSERT_GT(gross_slip_at, 0) << "never reached gross slip";
  EXPECT_NEAR(gross_slip_at, predicted_gross_slip, 0.1 * predicted_gross_slip);
}
