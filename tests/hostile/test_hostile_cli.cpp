// Outputs and messages a careless user met (issue 37): an output path that
// cannot be written is refused before any work and leaves nothing; a folder
// output is never overwritten; a folder where a file belongs is named as a
// directory; "--option=value" works; a damaged PNG is one line, never libpng's
// own; `process` fails when most of its frames cannot be read; and every
// command numbers frames by their 0-based index in the source.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "cli_runner.hpp"
#include "core/csv_table.hpp"
#include "scratch_dir.hpp"
#include "test_paths.hpp"

namespace {

using namespace onetip;
using namespace onetip::test_support;
namespace fs = std::filesystem;

const std::string kPress = shippedScenario("press");

std::vector<std::string> frameColumn(const std::string& csv) {
  std::vector<std::string> frames;
  for (const auto& row : readCsv(csv).rows) frames.push_back(row[0]);
  return frames;
}

// The numbers after "frame" at the start of each printed line.
std::vector<std::string> printedFrames(const std::string& out_file, const std::string& line_start) {
  std::vector<std::string> frames;
  std::istringstream in(readText(out_file));
  const std::regex pattern("^" + line_start + "\\s*([0-9]+)\\b.*");
  std::smatch m;
  for (std::string line; std::getline(in, line);)
    if (std::regex_match(line, m, pattern)) frames.push_back(m[1]);
  return frames;
}

// Four rendered frames of press.yaml with the simulator's calibration and pattern, made once,
// and a four-frame tap (0.1 s at 30 fps) for the commands that play a whole scenario.
class HostileCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scratch_ = new ScratchDir("onetip-hostile-cli");
    std::ofstream(tap()) << "name: tap\nfps: 30\nindenters:\n  - shape: ellipsoid\n    semi_axes: [7, 9, 6]\n"
                            "    keyframes:\n      - {t: 0.0, x: 0, y: 0, depth: -0.3}\n      - {t: 0.1, depth: 0.6}\n";
    const CliRun r =
        runCli("sim --quiet --frames 4 --scenario " + kPress + " --out " + sim().string(), scratch_->file("sim.err"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  static void TearDownTestSuite() {
    delete scratch_;
    scratch_ = nullptr;
  }
  static fs::path sim() { return scratch_->path() / "sim"; }
  static std::string tap() { return scratch_->file("tap.yaml"); }
  static std::string rig() {
    return " --calib " + (sim() / "calib.yaml").string() + " --pattern " + (sim() / "pattern.yaml").string();
  }
  // A copy of the four frames in `dir`/frames.
  static fs::path copyFrames(const ScratchDir& dir) {
    const fs::path frames = dir.path() / "frames";
    fs::copy(sim() / "frames", frames);
    return frames;
  }
  static ScratchDir* scratch_;
};
ScratchDir* HostileCli::scratch_ = nullptr;

TEST_F(HostileCli, SimChecksItsContactSheetPathBeforeRenderingAndLeavesNothing) {
  const ScratchDir dir("onetip-hostile-cli");
  const std::string out = dir.file("out");
  const std::string run = "sim --quiet --frames 3 --scenario " + kPress + " --out " + out + " --contact-sheet ";
  CliRun r = runCli(run + dir.file("nodir/x.png"), dir.file("err"));
  expectRefused(r, "nodir");
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out)) << "the run left its --out folder behind";
  expectRefused(runCli(run + dir.path().string(), dir.file("err")), "is a directory");
  EXPECT_FALSE(fs::exists(out));
  // the corrected command is not refused (nothing was left to refuse it), and writes both outputs
  r = runCli(run + dir.file("sheet.png"), dir.file("err"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(frameColumn(out + "/gt_pose.csv").size(), 3u);
  EXPECT_GT(fs::file_size(dir.file("sheet.png")), 1000u);
  EXPECT_FALSE(anyEntryContains(dir.path(), ".tmp."));
}

TEST_F(HostileCli, DemoRefusesAFolderThatHoldsSomethingLikeSim) {
  const ScratchDir dir("onetip-hostile-cli");
  const fs::path mine = dir.path() / "mine";
  fs::create_directory(mine);
  std::ofstream(mine / "keep.txt") << "mine";
  expectRefused(runCli("demo --scenario " + tap() + " --out " + mine.string(), dir.file("err")), "not an empty folder");
  EXPECT_EQ(readText((mine / "keep.txt").string()), "mine");
  EXPECT_FALSE(fs::exists(mine / "est_pose.csv"));
  // a first run fills a new folder; the same command again is refused, the first run's files untouched
  const std::string out = dir.file("demo");
  CliRun r = runCli("demo --scenario " + tap() + " --out " + out, dir.file("err"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string first = readText(out + "/est_pose.csv");
  EXPECT_EQ(frameColumn(out + "/est_pose.csv").size(), 4u);
  expectRefused(runCli("demo --scenario " + tap() + " --out " + out, dir.file("err")), "not an empty folder");
  EXPECT_EQ(readText(out + "/est_pose.csv"), first);
  // a folder that cannot be made is refused before the scenario plays
  expectRefused(runCli("demo --scenario " + tap() + " --out " + dir.file("nodir/demo"), dir.file("err")),
                "does not exist");
  EXPECT_FALSE(anyEntryContains(dir.path(), ".tmp."));
}

TEST_F(HostileCli, AFolderWhereAFileBelongsIsNamedAsADirectory) {
  const ScratchDir dir("onetip-hostile-cli");
  const std::string folder = dir.file("a_folder");
  fs::create_directory(folder);
  const std::string frames = (sim() / "frames").string();
  const std::string pose = dir.file("pose.csv");
  expectRefused(runCli("sim --field-only --scenario " + folder + " --out " + dir.file("o"), dir.file("err")),
                "a_folder: is a directory");
  expectRefused(runCli("process --quiet --input " + frames + " --calib " + folder + " --pattern " +
                           (sim() / "pattern.yaml").string() + " --out " + pose,
                       dir.file("err")),
                "a_folder: is a directory");
  const CliRun ref = runCli("process --quiet --input " + frames + rig() + " --out " + pose + " --reference " + folder,
                            dir.file("err"));
  expectRefused(ref, "a_folder: is a directory");
  EXPECT_EQ(ref.err.find("9223372036854775807"), std::string::npos) << ref.err;
  expectRefused(runCli("process --quiet --input " + frames + rig() + " --out " + folder, dir.file("err")),
                "is a directory");
  std::ofstream(dir.file("q.csv")) << "s1\n1\n";
  expectRefused(runCli("render --dataset " + folder + " --queries " + dir.file("q.csv") + " --out " + dir.file("m.csv"),
                       dir.file("err")),
                "a_folder: is a directory");
  EXPECT_FALSE(fs::exists(pose));
  EXPECT_FALSE(fs::exists(dir.file("m.csv")));
}

TEST_F(HostileCli, AnOptionTakesItsValueAfterAnEqualsSignToo) {
  const ScratchDir dir("onetip-hostile-cli");
  const std::string out = dir.file("a=b");  // only the first '=' splits
  CliRun r = runCli("sim --quiet --field-only --frames=2 --scenario=" + kPress + " --out=" + out, dir.file("err"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(frameColumn(out + "/gt_pose.csv").size(), 2u);
  expectRefused(runCli("sim --quiet=yes --field-only --frames 2 --scenario " + kPress + " --out " + dir.file("o"),
                       dir.file("err")),
                "'--quiet' is a switch and takes no value");
  expectRefused(runCli("sim --quiet --frames= --scenario " + kPress + " --out " + dir.file("o"), dir.file("err")),
                "'--frames': '' is not an integer");
  EXPECT_FALSE(fs::exists(dir.file("o")));
}

TEST_F(HostileCli, ADamagedPngIsOneLineOfOursNeverLibpngsOwn) {
  const ScratchDir dir("onetip-hostile-cli");
  const fs::path frames = copyFrames(dir);
  fs::resize_file(frames / "000002.png", fs::file_size(frames / "000002.png") / 3);  // truncated
  {  // one byte changed inside the first IDAT chunk's data: a CRC error
    std::string bytes = readText((frames / "000003.png").string());
    const size_t idat = bytes.find("IDAT");
    ASSERT_NE(idat, std::string::npos);
    bytes[idat + 40] = static_cast<char>(bytes[idat + 40] ^ 0x55);
    std::ofstream(frames / "000003.png", std::ios::binary) << bytes;
  }
  const CliRun r =
      runCli("process --quiet --input " + frames.string() + rig() + " --out " + dir.file("pose.csv"), dir.file("err"));
  EXPECT_EQ(r.exit_code, 0) << r.err;  // 2 of 4 frames: half, not more
  EXPECT_EQ(r.err.find("libpng"), std::string::npos) << r.err;
  for (const char* name : {"000002.png", "000003.png"}) {
    const size_t at = r.err.find(std::string(name) + ": cannot decode the PNG: ");
    EXPECT_NE(at, std::string::npos) << name << ": " << r.err;
    EXPECT_EQ(r.err.find(name, at + 1), std::string::npos) << name << " named once: " << r.err;
  }
  EXPECT_NE(r.err.find("2 of 4 frames could not be read or used"), std::string::npos) << r.err;
  EXPECT_EQ(frameColumn(dir.file("pose.csv")), (std::vector<std::string>{"0", "1"}));
}

TEST_F(HostileCli, ProcessFailsWhenMoreThanHalfOfTheFramesCannotBeRead) {
  const ScratchDir dir("onetip-hostile-cli");
  const fs::path frames = copyFrames(dir);
  for (const char* name : {"000001.png", "000002.png", "000003.png"}) std::ofstream(frames / name) << "not a png";
  const std::string pose = dir.file("pose.csv"), markers = dir.file("markers.csv");
  CliRun r = runCli("process --quiet --input " + frames.string() + rig() + " --out " + pose + " --markers " + markers,
                    dir.file("err"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("3 of 4 frames could not be read or used"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("nothing is written"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(pose));
  EXPECT_FALSE(fs::exists(markers));
  EXPECT_FALSE(anyEntryContains(dir.path(), ".tmp."));
  // one unreadable frame of four: written, exit status 0, and the count said
  fs::copy_file(sim() / "frames/000001.png", frames / "000001.png", fs::copy_options::overwrite_existing);
  fs::copy_file(sim() / "frames/000002.png", frames / "000002.png", fs::copy_options::overwrite_existing);
  r = runCli("process --quiet --input " + frames.string() + rig() + " --out " + pose, dir.file("err"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("1 of 4 frames could not be read or used and are not in"), std::string::npos) << r.err;
  EXPECT_EQ(frameColumn(pose), (std::vector<std::string>{"0", "1", "2"}));
}

TEST_F(HostileCli, EveryCommandNumbersFramesByTheirIndexInTheSource) {
  const ScratchDir dir("onetip-hostile-cli");
  const std::vector<std::string> all{"0", "1", "2", "3"};
  // sim: the printed lines and gt_pose.csv
  const std::string out = dir.file("out.txt");
  CliRun r = runCliWithOutput("sim --scenario " + tap() + " --out " + dir.file("sim"), out, dir.file("err"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(printedFrames(out, "frame"), all);
  EXPECT_EQ(frameColumn(dir.file("sim/gt_pose.csv")), all);
  // demo: the printed lines, est_pose.csv and gt_pose.csv
  r = runCliWithOutput("demo --scenario " + tap() + " --out " + dir.file("demo"), out, dir.file("err"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(printedFrames(out, "\\s*"), all);
  EXPECT_EQ(frameColumn(dir.file("demo/est_pose.csv")), all);
  EXPECT_EQ(frameColumn(dir.file("demo/gt_pose.csv")), all);
  // process over a folder whose frame 1 cannot be read: the others keep their index
  const fs::path frames = copyFrames(dir);
  std::ofstream(frames / "000001.png") << "not a png";
  r = runCliWithOutput("process --input " + frames.string() + rig() + " --out " + dir.file("pose.csv"), out,
                       dir.file("err"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> gap{"0", "2", "3"};
  EXPECT_EQ(printedFrames(out, "frame"), gap);
  EXPECT_EQ(frameColumn(dir.file("pose.csv")), gap);
  EXPECT_NE(r.err.find("frame 1 skipped: 000001.png"), std::string::npos) << r.err;
  // record keeps the source's indices, and processing the session gives them back
  r = runCli("record --input " + frames.string() + rig() + " --out " + dir.file("session"), dir.file("err"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(frameColumn(dir.file("session/session.csv")), gap);
  r = runCli("process --quiet --input " + dir.file("session") + rig() + " --out " + dir.file("replay.csv"),
             dir.file("err"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(frameColumn(dir.file("replay.csv")), gap);
}

}  // namespace
