// A recording that survives bad luck (issue 39, items 4 and 5): `onetip record`
// killed with SIGKILL at random moments leaves a folder that `process --input`
// replays up to its last complete frame with the live run's timestamps; a write
// that fails (a file-size limit standing in for a full disk) keeps the frames
// so far as a whole session; a commit that fails keeps the staging folder and
// names it; a live run in another PID namespace keeps its staging.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <random>

#include "cli_runner.hpp"
#include "core/csv_table.hpp"
#include "scratch_dir.hpp"
#include "test_paths.hpp"

namespace {

using namespace onetip;
using namespace onetip::test_support;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const std::string kDemo = shippedScenario("demo_touch");

// The one entry of `dir` whose name starts with `prefix`, or an empty path.
fs::path entryStartingWith(const fs::path& dir, const std::string& prefix) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.path().filename().string().rfind(prefix, 0) == 0) return e.path();
  return {};
}

std::string processArgs(const fs::path& session, const std::string& calib_dir, const std::string& out) {
  return "process --quiet --input " + session.string() + " --calib " + calib_dir + "/calib.yaml --pattern " + calib_dir +
         "/pattern.yaml --out " + out;
}

TEST(HostileRecording, KilledAtRandomMomentsItReplaysEveryCompleteFrameWithItsTimestamps) {
  const ScratchDir dir("onetip-hostile-rec");
  constexpr int kFrames = 16;
  const std::string frames = " --frames " + std::to_string(kFrames);
  const auto ref_start = Clock::now();
  const CliRun ref = runCli("record --input sim:" + kDemo + frames + " --out " + dir.file("ref"), dir.file("err"));
  ASSERT_EQ(ref.exit_code, 0) << ref.err;
  const auto ref_ms = std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - ref_start).count();
  const CsvTable ref_rows = readCsv(dir.file("ref/session.csv"));
  ASSERT_EQ(ref_rows.rows.size(), static_cast<size_t>(kFrames));
  const CliRun ref_replay = runCli(processArgs(dir.path() / "ref", dir.file("ref"), dir.file("ref_pose.csv")), dir.file("err"));
  ASSERT_EQ(ref_replay.exit_code, 0) << ref_replay.err;
  const CsvTable ref_pose = readCsv(dir.file("ref_pose.csv"));

  const unsigned seed = std::random_device{}();
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> delay_ms(0, static_cast<int>(ref_ms));  // a moment of a whole run
  int replayed = 0, killed = 0;
  for (int attempt = 0; attempt < 10; ++attempt) {
    const std::string name = "run" + std::to_string(attempt);
    const int delay = delay_ms(random);
    std::optional<Clock::time_point> kill_at;
    const CliRun run = runCli(
        "record --input sim:" + kDemo + frames + " --out " + dir.file(name), dir.file("err"),
        [&] {  // a random moment once the recording has begun
          if (!kill_at && !entryStartingWith(dir.path(), name + ".partial.").empty())
            kill_at = Clock::now() + std::chrono::milliseconds(delay);
          return kill_at && Clock::now() >= *kill_at;
        },
        SIGKILL);
    SCOPED_TRACE("seed " + std::to_string(seed) + ", attempt " + std::to_string(attempt) + ", killed " +
                 std::to_string(delay) + " ms in");
    fs::path left = dir.path() / name;  // finished before the kill landed: the committed session
    if (run.signalled && run.exit_code != 0) {
      ++killed;
      ASSERT_EQ(run.exit_code, 128 + SIGKILL) << run.err;
      left = entryStartingWith(dir.path(), name + ".partial.");
      if (left.empty()) left = dir.path() / name;  // killed between its commit and its exit: the session is whole
      ASSERT_TRUE(fs::exists(left)) << "the killed recording was not kept";
    } else {
      ASSERT_EQ(run.exit_code, 0) << run.err;
    }
    const fs::path csv = left / "session.csv";
    if (!fs::exists(csv)) continue;  // killed before its first row could exist
    const CsvTable rows = readCsv(csv.string());
    ASSERT_LE(rows.rows.size(), ref_rows.rows.size());
    for (size_t i = 0; i < rows.rows.size(); ++i) {
      EXPECT_EQ(rows.rows[i], ref_rows.rows[i]) << "row " << i;  // index, exact timestamp, file
      EXPECT_EQ(readText((left / rows.rows[i][2]).string()), readText(dir.file("ref/" + rows.rows[i][2])));
    }
    const std::string pose = dir.file(name + "_pose.csv");
    const CliRun replay = runCli(processArgs(left, dir.file("ref"), pose), dir.file("err"));
    if (rows.rows.empty()) {
      EXPECT_NE(replay.err.find("no recorded frames"), std::string::npos) << replay.err;
      continue;
    }
    ASSERT_EQ(replay.exit_code, 0) << replay.err;
    const CsvTable replayed_pose = readCsv(pose);
    ASSERT_EQ(replayed_pose.rows.size(), rows.rows.size());
    for (size_t i = 0; i < replayed_pose.rows.size(); ++i) EXPECT_EQ(replayed_pose.rows[i], ref_pose.rows[i]);
    ++replayed;
  }
  EXPECT_GT(killed, 0) << "every run ended before its kill";
  EXPECT_GT(replayed, 0) << "no attempt left a frame to replay";
}

// Small same-size frames, so a file-size limit can fall between frames; `noisy` ones compress badly.
void writeFrames(const fs::path& folder, int count, int noisy_from) {
  fs::create_directories(folder);
  for (int i = 0; i < count; ++i) {
    cv::Mat grey(48, 64, CV_8UC1);
    for (int c = 0; c < grey.cols; ++c) grey.col(c).setTo(((c / 8 + i) % 2) * 200 + 20);  // stripes: not blank
    if (i >= noisy_from) cv::randu(grey, 0, 256);
    char name[32];
    std::snprintf(name, sizeof name, "%04d.png", i);
    ASSERT_TRUE(cv::imwrite((folder / name).string(), grey));
  }
}

TEST(HostileRecording, AWriteThatFailsKeepsTheFramesSoFarAsAWholeSession) {
  const ScratchDir dir("onetip-hostile-rec");
  writeFrames(dir.path() / "smooth", 60, 60);  // session.csv reaches the limit first
  writeFrames(dir.path() / "noisy", 12, 5);    // frame 5 is over the limit
  for (const std::string source : {"smooth", "noisy"}) {
    SCOPED_TRACE(source);
    const fs::path out = dir.path() / (source + "_session");
    const CliRun run = runCli("record --input " + dir.file(source) + " --out " + out.string(), dir.file("err"), {}, 0,
                              fileSizeLimit(source == "smooth" ? 1024 : 2048));
    EXPECT_EQ(run.exit_code, 1) << run.err;
    EXPECT_NE(run.err.find("File too large"), std::string::npos) << run.err;  // the cause, named
    EXPECT_NE(run.err.find(source == "smooth" ? "session.csv" : "000005.png"), std::string::npos) << run.err;
    const CsvTable rows = readCsv((out / "session.csv").string());
    ASSERT_GE(rows.rows.size(), 5u);
    EXPECT_LT(rows.rows.size(), source == "smooth" ? 60u : 6u);
    for (size_t i = 0; i < rows.rows.size(); ++i) {
      EXPECT_EQ(rows.rows[i][0], std::to_string(i));
      EXPECT_TRUE(fs::is_regular_file(out / rows.rows[i][2])) << rows.rows[i][2];
    }
    EXPECT_EQ(static_cast<size_t>(std::distance(fs::directory_iterator(out / "frames"), {})), rows.rows.size());
    EXPECT_TRUE(entryStartingWith(dir.path(), source + "_session.partial.").empty());
  }
}

TEST(HostileRecording, ACommitThatFailsKeepsTheStagingFolderAndNamesIt) {
  const ScratchDir dir("onetip-hostile-rec");
  const fs::path out = dir.path() / "session";
  const CliRun run = runCli(
      "record --input sim:" + kDemo + " --frames 8 --out " + out.string(), dir.file("err"),
      [&] {  // another run fills the output folder meanwhile
        if (entryStartingWith(dir.path(), "session.partial.").empty()) return false;
        fs::create_directory(out);
        std::ofstream(out / "theirs") << "x";
        return true;
      },
      0);
  ASSERT_TRUE(run.signalled);
  EXPECT_EQ(run.exit_code, 1) << run.err;
  const fs::path kept = entryStartingWith(dir.path(), "session.partial.");
  ASSERT_FALSE(kept.empty());
  EXPECT_NE(run.err.find(kept.filename().string()), std::string::npos) << run.err;
  EXPECT_EQ(readCsv((kept / "session.csv").string()).rows.size(), 8u);
  EXPECT_EQ(readText((out / "theirs").string()), "x");
}

}  // namespace
