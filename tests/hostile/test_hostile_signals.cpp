// Ctrl-C and SIGTERM in every command that writes files (issue 17): each is
// interrupted mid-run, once its staging output exists, and must exit 130 with
// complete outputs of the frames done so far (process, demo, view) or nothing
// (sim), and no staging file left behind.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli_runner.hpp"
#include "core/csv_table.hpp"
#include "scratch_dir.hpp"
#include "test_paths.hpp"

namespace {

using namespace onetip;
using namespace onetip::test_support;
namespace fs = std::filesystem;

const std::string kDemo = shippedScenario("demo_touch");  // 121 frames, ~4 s to render

// Frame numbers 0, 1, 2, ... with no gap and no repeat, and the CONVENTIONS header.
// An estimate (pose.csv, est_pose.csv) has the sd columns, the simulator's truth (gt_pose.csv) only the nine.
void expectWholePoseCsv(const std::string& path, size_t at_most, bool truth = false) {
  const CsvTable t = readCsv(path);
  std::vector<std::string> header{"frame", "contact", "state", "dx", "dy", "dz", "yaw", "pitch", "roll"};
  if (!truth) header.insert(header.end(), {"sd_dx", "sd_dy", "sd_dz", "sd_yaw", "sd_pitch", "sd_roll"});
  EXPECT_EQ(t.header, header) << path;
  ASSERT_GE(t.rows.size(), 1u);
  EXPECT_LT(t.rows.size(), at_most) << "the run was not interrupted";
  for (size_t i = 0; i < t.rows.size(); ++i) EXPECT_EQ(t.rows[i][0], std::to_string(i));
}

TEST(HostileSignals, ProcessWritesTheFramesDoneSoFar) {
  for (const int sig : {SIGINT, SIGTERM}) {
    const ScratchDir dir("onetip-hostile-sig");
    const std::string pose = dir.file("pose.csv"), markers = dir.file("markers.csv");
    const CliRun sim = runCli("sim --quiet --field-only --frames 1 --scenario " + kDemo + " --out " + dir.file("s"),
                              dir.file("err"));
    ASSERT_EQ(sim.exit_code, 0) << sim.err;
    int seen = 0;
    const CliRun run = runCli(
        "process --quiet --input sim:" + kDemo + " --calib " + dir.file("s/calib.yaml") + " --pattern " +
            dir.file("s/pattern.yaml") + " --out " + pose + " --markers " + markers,
        dir.file("err"), [&] { return anyEntryContains(dir.path(), "pose.csv.tmp.") && ++seen > 25; }, sig);
    ASSERT_TRUE(run.signalled) << run.err;
    EXPECT_EQ(run.exit_code, 130) << run.err;
    expectWholePoseCsv(pose, 121);
    EXPECT_TRUE(fs::exists(markers));
    EXPECT_FALSE(anyEntryContains(dir.path(), ".tmp.")) << sig;
  }
}

TEST(HostileSignals, SimWritesNothingAndLeavesNoStaging) {
  const ScratchDir dir("onetip-hostile-sig");
  const fs::path out = dir.path() / "out";
  int seen = 0;
  const CliRun run = runCli("sim --quiet --scenario " + kDemo + " --out " + out.string(), dir.file("err"),
                            [&] { return anyEntryContains(dir.path(), "out.tmp.") && ++seen > 25; }, SIGTERM);
  ASSERT_TRUE(run.signalled) << run.err;
  EXPECT_EQ(run.exit_code, 130) << run.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(anyEntryContains(dir.path(), ".tmp."));
}

TEST(HostileSignals, DemoWritesTheFramesDoneSoFar) {
  const ScratchDir dir("onetip-hostile-sig");
  const fs::path out = dir.path() / "demo";
  int seen = 0;
  // The folder is filled under a staging folder beside it ("demo.tmp.<pid>.<random>") and appears at the end.
  const CliRun run = runCli("demo --scenario " + kDemo + " --out " + out.string(), dir.file("err"),
                            [&] { return anyEntryContains(dir.path(), "demo.tmp.") && ++seen > 25; }, SIGINT);
  ASSERT_TRUE(run.signalled) << run.err;
  EXPECT_EQ(run.exit_code, 130) << run.err;
  expectWholePoseCsv((out / "est_pose.csv").string(), 121);
  expectWholePoseCsv((out / "gt_pose.csv").string(), 121, true);
  EXPECT_TRUE(fs::exists(out / "contact_sheet.png"));
  EXPECT_FALSE(anyEntryContains(out, ".tmp."));
  EXPECT_FALSE(anyEntryContains(dir.path(), ".tmp."));
}

TEST(HostileSignals, RecordKeepsTheFramesSoFarAsAReplayableSession) {
  const ScratchDir dir("onetip-hostile-sig");
  const fs::path session = dir.path() / "session";
  int seen = 0;
  const CliRun run = runCli("record --input sim:" + kDemo + " --out " + session.string(), dir.file("err"),
                            [&] { return anyEntryContains(dir.path(), "session.partial.") && ++seen > 25; }, SIGINT);
  ASSERT_TRUE(run.signalled) << run.err;
  EXPECT_EQ(run.exit_code, 130) << run.err;
  const CsvTable frames = readCsv((session / "session.csv").string());
  ASSERT_GE(frames.rows.size(), 1u);
  EXPECT_LT(frames.rows.size(), 121u);
  EXPECT_FALSE(anyEntryContains(dir.path(), ".tmp."));
  EXPECT_FALSE(anyEntryContains(dir.path(), ".partial."));
  const CliRun replay = runCli("process --quiet --input " + session.string() + " --calib " +
                                   (session / "calib.yaml").string() + " --pattern " + (session / "pattern.yaml").string() +
                                   " --out " + dir.file("pose.csv"),
                               dir.file("err"));
  ASSERT_EQ(replay.exit_code, 0) << replay.err;
  expectWholePoseCsv(dir.file("pose.csv"), frames.rows.size() + 1);
  EXPECT_EQ(readCsv(dir.file("pose.csv")).rows.size(), frames.rows.size());
}

}  // namespace
