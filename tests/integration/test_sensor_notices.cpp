// What the sensor says about itself reaches a user of the command line
// (tools/sensor_notices.hpp): `onetip process` on rendered world scenarios
// names, on stderr, the markers the simulator hid (its own list, not a copy)
// and the camera's shift at the frame the simulator moved it, once. A shifted
// mirror (vision/view_shift.hpp) is named too, starts no contact, and the
// press after it reads as the simulator's truth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "core/csv_table.hpp"
#include "scratch_dir.hpp"
#include "sim/scenario.hpp"
#include "sim/simulator.hpp"
#include "test_paths.hpp"

namespace {

std::string worldScenario(const std::string& name) {
  return std::string(onetip::test::testDataDir()) + "/scenarios/world/" + name + ".yaml";
}

// The stderr of `onetip process --quiet` over sim:<scenario>.
std::string processNotices(const std::string& scenario) {
  const onetip::test_support::ScratchDir dir("onetip-notices");
  const std::string cmd = std::string(onetip::test::cliPath()) + " process --quiet --input sim:" + scenario +
                          " --out " + dir.file("pose.csv") + " >/dev/null 2>" + dir.file("err");
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::ifstream in(dir.file("err"));
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> linesMatching(const std::string& text, const std::string& needle) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.find(needle) != std::string::npos) out.push_back(line);
  return out;
}

}  // namespace

TEST(SensorNotices, HiddenMarkersAreNamedAsTheSimulatorHidThem) {
  const std::string path = worldScenario("damaged_gel");
  const onetip::sim::Scenario sc = onetip::sim::loadScenario(path);
  const std::vector<int> truth = sc.world.damage.hiddenIds(onetip::sim::Simulator(sc).pattern());
  ASSERT_FALSE(truth.empty());
  const std::vector<std::string> lines = linesMatching(processNotices(path), "markers hidden");
  ASSERT_EQ(lines.size(), 1u);
  std::vector<int> named;
  const std::string ids = lines[0].substr(lines[0].find("ids") + 3);
  const std::regex number("[0-9]+");
  for (auto it = std::sregex_iterator(ids.begin(), ids.end(), number); it != std::sregex_iterator(); ++it)
    named.push_back(std::stoi(it->str()));
  EXPECT_EQ(named, truth) << lines[0];
}

TEST(SensorNotices, ACameraShiftIsNamedOnceAtItsFrame) {
  const std::string path = worldScenario("camera_shift");
  const onetip::sim::Scenario sc = onetip::sim::loadScenario(path);
  const long long shift_frame = std::llround(sc.world.camera_shift.at_s * sc.fps);
  const std::vector<std::string> lines = linesMatching(processNotices(path), "the camera moved");
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("frame " + std::to_string(shift_frame) + ":"), std::string::npos) << lines[0];
}

TEST(SensorNotices, AShiftedMirrorIsNamedAndThePressAfterItReadsTrue) {
  const std::string path = worldScenario("mirror_shift");
  const onetip::sim::Scenario sc = onetip::sim::loadScenario(path);
  const long long shift_frame = std::llround(sc.world.camera_shift.at_s * sc.fps);
  const onetip::test_support::ScratchDir dir("onetip-mirror");
  const std::string out = dir.file("demo");
  const std::string cmd = std::string(onetip::test::cliPath()) + " demo --scenario " + path + " --out " + out +
                          " >/dev/null 2>" + dir.file("err");
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::ifstream err_in(dir.file("err"));
  std::stringstream err;
  err << err_in.rdbuf();
  const std::vector<std::string> lines = linesMatching(err.str(), "moved against the pad");
  ASSERT_EQ(lines.size(), 1u) << err.str();
  EXPECT_NE(lines[0].find("left mirror"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("frame " + std::to_string(shift_frame) + ":"), std::string::npos) << lines[0];
  const onetip::CsvTable est = onetip::readCsv(out + "/est_pose.csv");
  const onetip::CsvTable gt = onetip::readCsv(out + "/gt_pose.csv");
  ASSERT_EQ(est.rows.size(), gt.rows.size());
  const size_t est_contact = est.column("contact", "est_pose.csv"), gt_contact = gt.column("contact", "gt_pose.csv");
  const size_t est_dz = est.column("dz", "est_pose.csv"), gt_dz = gt.column("dz", "gt_pose.csv");
  double deepest_est = 0, deepest_gt = 0;
  for (size_t k = 0; k < est.rows.size(); ++k) {
    EXPECT_EQ(est.rows[k][est_contact], gt.rows[k][gt_contact]) << "frame " << k;
    deepest_est = std::max(deepest_est, std::stod(est.rows[k][est_dz]));
    deepest_gt = std::max(deepest_gt, std::stod(gt.rows[k][gt_dz]));
  }
  EXPECT_NEAR(deepest_est, deepest_gt, 0.02);
}
