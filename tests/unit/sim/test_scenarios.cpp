// Scenario files: every shipped scenario loads and plays; bad files name the
// bad key; `onetip sim` writes whole output or none.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/csv_table.hpp"
#include "core/error.hpp"
#include "sim/scenario.hpp"
#include "sim/simulator.hpp"
#include "scratch_dir.hpp"
#include "test_paths.hpp"

using namespace onetip;
using namespace onetip::sim;
namespace fs = std::filesystem;

namespace {
const fs::path kScenarios = fs::path(onetip::test::sourceDir()) / "samples" / "scenarios";

std::string loadError(const std::string& text) {
  const test_support::ScratchDir scratch("onetip-scenario");
  const fs::path p = scratch.path() / "bad_scenario.yaml";
  std::ofstream(p) << "%YAML:1.0\n---\n" << text;
  try {
    loadScenario(p.string());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

int run(const std::string& cmd) { return std::system((cmd + " >/dev/null 2>&1").c_str()); }
}  // namespace

TEST(Scenarios, EveryShippedScenarioLoadsAndPlays) {
  int count = 0;
  for (const auto& e : fs::directory_iterator(kScenarios)) {
    if (e.path().extension() != ".yaml") continue;
    ++count;
    Scenario sc = loadScenario(e.path().string());
    EXPECT_EQ(sc.name + ".yaml", e.path().filename().string()) << "scenario files are named for their scenario";
    SimulatorOptions o;
    o.frames = 12;
    Simulator sim(sc, o);
    bool touched = sc.isCalibration();
    while (!sim.done()) touched |= sim.next().in_contact;
    EXPECT_TRUE(touched) << e.path() << " never touches the pad";
  }
  EXPECT_GE(count, 15);
}

TEST(Scenarios, BadFilesNameTheBadKey) {
  const std::string finger = "name: x\nindenters:\n  - shape: ellipsoid\n    keyframes:\n";
  EXPECT_NE(loadError("indenters: []\n").find("name"), std::string::npos);
  EXPECT_NE(loadError(finger + "      - {t: 0, depth: 1}\n      - {t: 0, depth: 2}\n").find("keyframes[1].t"),
            std::string::npos);
  EXPECT_NE(loadError(finger + "      - {t: 0, dpeth: 1}\n").find("dpeth"), std::string::npos);
  EXPECT_NE(loadError("name: x\nindenters:\n  - shape: cube\n    keyframes:\n      - {t: 0}\n").find("shape"),
            std::string::npos);
  EXPECT_NE(loadError("name: x\npad: {rows: 1}\nindenters: []\n").find("rows"), std::string::npos);
  EXPECT_NE(loadError("name: x\nimage: {noise_sigma: -3}\nindenters: []\n").find("noise_sigma"), std::string::npos);
  EXPECT_NE(loadError("name: x\nindenters:\n  - shape: sphere\n    radius: 0\n    keyframes:\n      - {t: 0}\n")
                .find("semi_axes"),
            std::string::npos);
}

TEST(Scenarios, SimCommandWritesWholeOutputOrNone) {
  const test_support::ScratchDir scratch("onetip-sim-out");
  const fs::path out = scratch.path() / "out";
  const std::string cli = onetip::test::cliPath();
  ASSERT_EQ(run(cli + " sim --scenario " + (kScenarios / "press.yaml").string() + " --out " + out.string() +
                " --frames 5 --quiet"),
            0);
  for (const char* f : {"gt_pose.csv", "gt_markers.csv", "calib.yaml", "pattern.yaml", "frames/000004.png"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  const CsvTable pose = readCsv((out / "gt_pose.csv").string());
  EXPECT_EQ(pose.header, (std::vector<std::string>{"frame", "contact", "state", "dx", "dy", "dz", "yaw", "pitch", "roll"}));
  EXPECT_EQ(pose.rows.size(), 5u);
  const CsvTable markers = readCsv((out / "gt_markers.csv").string());
  EXPECT_EQ(markers.rows.size(), 5u * 17 * 17);

  // a bad scenario: non-zero exit, and neither a new folder nor a staging folder is left
  const fs::path bad = scratch.path() / "bad.yaml";
  std::ofstream(bad) << "%YAML:1.0\n---\nname: bad\nindenters:\n  - shape: ellipsoid\n    keyframes: 3\n";
  const fs::path out2 = out.string() + "_bad";
  EXPECT_NE(run(cli + " sim --scenario " + bad.string() + " --out " + out2.string()), 0);
  EXPECT_FALSE(fs::exists(out2));
  for (const auto& e : fs::directory_iterator(scratch.path()))
    EXPECT_EQ(e.path().string().find(out2.filename().string() + ".tmp"), std::string::npos);
  EXPECT_NE(run(cli + " sim --scenario " + (kScenarios / "press.yaml").string()), 0);  // --out missing
}
