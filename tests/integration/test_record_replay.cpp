// Record and replay (issue 17): `onetip record` keeps a live source's frames,
// and `onetip process --input SESSION` must reproduce the live run's pose.csv
// and markers.csv byte for byte. The live run is the simulated camera
// (sim:SCENARIO) processed directly; the reference is that run's own output.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/csv_table.hpp"
#include "scratch_dir.hpp"
#include "test_paths.hpp"
#include "sanitizer_leg.hpp"

namespace {

namespace fs = std::filesystem;
const fs::path kSource(onetip::test::sourceDir());

int run(const std::string& args) {
  return std::system((std::string(onetip::test::cliPath()) + " " + args + " >/dev/null 2>&1").c_str());
}

std::string readAll(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(RecordReplay, ProcessingASessionReproducesTheLiveRunExactly) {
  ONETIP_SWEEP_RUNS_IN_RELEASE_ONLY();
  const onetip::test_support::ScratchDir dir("onetip-record-replay");
  const std::string scenario = (kSource / "samples/scenarios/slide_x.yaml").string();
  const fs::path session = dir.path() / "session";
  ASSERT_EQ(run("record --input sim:" + scenario + " --out " + session.string()), 0);
  const std::string calib = (session / "calib.yaml").string(), pattern = (session / "pattern.yaml").string();
  ASSERT_EQ(run("process --quiet --input sim:" + scenario + " --calib " + calib + " --pattern " + pattern + " --out " +
                dir.file("live.csv") + " --markers " + dir.file("live_markers.csv")),
            0);
  ASSERT_EQ(run("process --quiet --input " + session.string() + " --calib " + calib + " --pattern " + pattern +
                " --out " + dir.file("replay.csv") + " --markers " + dir.file("replay_markers.csv")),
            0);
  const onetip::CsvTable live = onetip::readCsv(dir.file("live.csv"));
  ASSERT_GT(live.rows.size(), 10u);
  int in_contact = 0;
  for (const auto& row : live.rows) in_contact += row[1] == "1";
  EXPECT_GT(in_contact, 5) << "the scenario must exercise the pose, not only the rest state";
  EXPECT_EQ(readAll(dir.file("replay.csv")), readAll(dir.file("live.csv")));
  EXPECT_EQ(readAll(dir.file("replay_markers.csv")), readAll(dir.file("live_markers.csv")));
  const onetip::CsvTable frames = onetip::readCsv((session / "session.csv").string());
  EXPECT_EQ(frames.rows.size(), live.rows.size());
  EXPECT_EQ(frames.rows[0][2], "frames/000000.png");  // decoded sources are kept losslessly
}

}  // namespace
