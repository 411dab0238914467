// The example scenarios of the world effects (tests/data/scenarios/world/;
// not under samples/scenarios, whose every file the front-end sweep holds to
// an undamaged pad's detection figures): each loads with its effect on,
// plays, touches, and reports no contact while nothing touches.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "sim/simulator.hpp"
#include "scratch_dir.hpp"
#include "test_paths.hpp"

using namespace onetip;
using namespace onetip::sim;
namespace fs = std::filesystem;

TEST(WorldScenarios, EveryExampleLoadsWithItsEffectAndTouchesOnlyWhenAFingerDoes) {
  int count = 0;
  for (const auto& e : fs::directory_iterator(fs::path(onetip::test::sourceDir()) / "tests/data/scenarios/world")) {
    if (e.path().extension() != ".yaml") continue;
    ++count;
    const Scenario sc = loadScenario(e.path().string());
    EXPECT_EQ(sc.name + ".yaml", e.path().filename().string());
    EXPECT_TRUE(sc.world.any()) << e.path();
    Simulator sim(sc);
    int touched = 0;
    while (!sim.done()) {
      const GroundTruthFrame& f = sim.next();
      int nodes = 0;
      for (int n : f.indenter_nodes) nodes += n;
      if (nodes == 0) {
        EXPECT_FALSE(f.in_contact) << e.path() << " t " << f.t;
      }
      touched += f.in_contact ? 1 : 0;
    }
    EXPECT_GT(touched, 0) << e.path();
  }
  EXPECT_EQ(count, 10);
}

TEST(WorldScenarios, BadEffectValuesNameTheirKey) {
  const test_support::ScratchDir scratch("onetip-world");
  const fs::path dir = scratch.path();
  const auto error = [&](const std::string& section) {
    const fs::path p = dir / "bad.yaml";
    std::ofstream(p) << "name: bad\n" << section << "\nindenters:\n  - shape: sphere\n    keyframes:\n      - {t: 0, depth: 1}\n";
    try {
      loadScenario(p.string());
    } catch (const std::exception& ex) {
      return std::string(ex.what());
    }
    return std::string();
  };
  EXPECT_NE(error("viscoelastic: {relaxation: 0.9}").find("relaxation"), std::string::npos);
  EXPECT_NE(error("drift: {time_s: 0.1}").find("time_s"), std::string::npos);
  EXPECT_NE(error("camera_shift: {view: top}").find("view"), std::string::npos);
  EXPECT_NE(error("damage: {ids: [289]}").find("ids"), std::string::npos);
  EXPECT_NE(error("light: {flicker: 2}").find("flicker"), std::string::npos);
  EXPECT_NE(error("light: {flickr: 0.1}").find("flickr"), std::string::npos);
}
