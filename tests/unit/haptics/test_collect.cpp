// Dataset collection with the sensor inside the display (calib/haptic_collection.hpp
// and `onetip collect`): a collection that is stopped (row limit, stop flag,
// SIGINT, a line cut short) and resumed gives exactly the dataset of the
// independent reference simulateDataset(); bad options give a one-line error
// and no output.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "calib/haptic_collection.hpp"
#include "core/error.hpp"
#include "haptics/biotac_like_sensor.hpp"
#include "haptics/dataset_binary.hpp"
#include "haptics/display_grid.hpp"
#include "haptics/tactile_dataset.hpp"
#include "scratch_dir.hpp"
#include "test_paths.hpp"

extern char** environ;

using namespace onetip;
using namespace onetip::haptics;
namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

size_t lineCount(const fs::path& p) {
  const std::string s = slurp(p);
  return static_cast<size_t>(std::count(s.begin(), s.end(), '\n'));
}

void expectSameDataset(const TactileDataset& a, const TactileDataset& b) {
  ASSERT_EQ(a.channels, b.channels);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.commands, b.commands);
  EXPECT_EQ(a.sensed, b.sensed);
}

struct Fixture {
  PlatformKinematics device;
  BiotacLikeSensor sensor;
  calib::SimulatedRig rig{device, sensor};
};

constexpr double kStep = 33.0;  // 5 angles per motor: 125 configurations

}  // namespace

TEST(Collect, StoppedAndResumedRunsEqualTheUninterruptedDataset) {
  Fixture f;
  const test_support::ScratchDir scratch("onetip-collect");
  const auto dir = scratch.path();
  calib::CollectionOptions o;
  o.step_deg = kStep;
  o.flush_every_rows = 7;
  o.out_path = (dir / "whole.csv").string();
  ASSERT_EQ(calib::collectDataset(f.rig, o).status, calib::CollectionResult::Status::complete);
  const TactileDataset reference = simulateDataset(f.device, f.sensor, kStep);
  expectSameDataset(readDatasetCsv(o.out_path), reference);
  EXPECT_FALSE(fs::exists(o.progressPath()));

  o.out_path = (dir / "pieces.csv").string();
  o.max_new_rows = 40;  // 1. a row limit
  auto r = calib::collectDataset(f.rig, o);
  EXPECT_EQ(r.status, calib::CollectionResult::Status::interrupted);
  EXPECT_EQ(r.rows, 40u);
  EXPECT_FALSE(fs::exists(o.out_path));
  EXPECT_EQ(lineCount(o.progressPath()), 2u + 40u);

  // 2. A write cut short: half of a line without its newline.
  const std::string cut = "93,30,6";
  std::ofstream(o.progressPath(), std::ios::app) << cut;
  // 3. A stop request after 25 more rows.
  o.max_new_rows = -1;
  std::atomic<bool> stop{false};
  size_t seen = 0;
  r = calib::collectDataset(f.rig, o, &stop, [&](const calib::CollectionProgress& p) {
    EXPECT_EQ(p.resumed, 40u);
    if (++seen == 25) stop = true;
  });
  EXPECT_EQ(r.status, calib::CollectionResult::Status::interrupted);
  EXPECT_EQ(r.resumed, 40u);
  EXPECT_EQ(r.rows, 65u);
  EXPECT_EQ(slurp(o.progressPath()).find(cut + "\n"), std::string::npos);

  // 4. Resume to the end.
  r = calib::collectDataset(f.rig, o);
  EXPECT_EQ(r.status, calib::CollectionResult::Status::complete);
  EXPECT_EQ(r.resumed, 65u);
  EXPECT_EQ(r.new_rows, 125u - 65u);
  EXPECT_EQ(slurp(dir / "pieces.csv"), slurp(dir / "whole.csv"));
  EXPECT_FALSE(fs::exists(o.progressPath()));

  // The binary format by extension.
  o.out_path = (dir / "whole.bin").string();
  calib::collectDataset(f.rig, o);
  ASSERT_TRUE(isBinaryDataset(o.out_path));
  expectSameDataset(loadDataset(o.out_path), reference);
}

TEST(Collect, RefusesAProgressFileOfOtherOptionsOrOffTheGrid) {
  Fixture f;
  const test_support::ScratchDir scratch("onetip-collect");
  const auto dir = scratch.path();
  calib::CollectionOptions o;
  o.step_deg = kStep;
  o.out_path = (dir / "d.csv").string();
  o.max_new_rows = 10;
  calib::collectDataset(f.rig, o);
  o.step_deg = 55.0;  // other grid
  EXPECT_THROW(calib::collectDataset(f.rig, o), InputError);
  o.step_deg = kStep;
  std::string text = slurp(o.progressPath());
  const size_t third = text.find('\n', text.find('\n') + 1) + 1;
  text.replace(third, 2, "31");  // the first row's m1 is 30
  std::ofstream(o.progressPath(), std::ios::trunc) << text;
  try {
    calib::collectDataset(f.rig, o);
    FAIL() << "a row off the grid was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line 3"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(o.out_path));
}

TEST(Collect, ProgressBarShowsFractionRateAndEta) {
  const std::string bar = calib::formatProgressBar({50, 200, 10, 2.0}, 10);
  EXPECT_EQ(bar.substr(0, 12), "[###.......]");  // 25 % of 10 columns, rounded
  EXPECT_NE(bar.find("25.0%"), std::string::npos) << bar;
  EXPECT_NE(bar.find("50/200 rows"), std::string::npos) << bar;
  EXPECT_NE(bar.find("20 rows/s"), std::string::npos) << bar;  // 40 new rows in 2 s
  EXPECT_NE(bar.find("ETA 8s"), std::string::npos) << bar;     // 150 rows at 20 rows/s: 7.5 s
}

namespace {

struct Exit {
  int status = -1;
  std::string stderr_text;
};

Exit runCli(const std::vector<std::string>& args, const fs::path& dir, bool interrupt_when_progress = false) {
  std::vector<std::string> all = {onetip::test::cliPath(), "collect"};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string err_path = (dir / "stderr.txt").string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 2, err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  EXPECT_EQ(posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  if (interrupt_when_progress) {
    const fs::path progress = dir / "d.csv.progress";
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (!(fs::exists(progress) && fs::file_size(progress) > 4096) && std::chrono::steady_clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    ::kill(pid, SIGINT);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(err_path)};
}

}  // namespace

TEST(CollectCli, SigintStopsCleanlyAndTheSameCommandResumes) {
  const test_support::ScratchDir scratch("onetip-collect");
  const auto dir = scratch.path();
  const std::vector<std::string> args = {"--step", "4", "--quiet", "--out", (dir / "d.csv").string()};
  const Exit stopped = runCli(args, dir, true);
  ASSERT_EQ(stopped.status, 1) << stopped.stderr_text;
  EXPECT_NE(stopped.stderr_text.find("resume"), std::string::npos) << stopped.stderr_text;
  EXPECT_FALSE(fs::exists(dir / "d.csv"));
  const size_t kept = lineCount(dir / "d.csv.progress");
  EXPECT_GT(kept, 2u);
  EXPECT_LT(kept, 2u + 42u * 42u * 42u);
  const Exit resumed = runCli(args, dir);
  ASSERT_EQ(resumed.status, 0) << resumed.stderr_text;
  expectSameDataset(readDatasetCsv((dir / "d.csv").string()),
                    simulateDataset(PlatformKinematics(), BiotacLikeSensor(), 4.0));
  EXPECT_FALSE(fs::exists(dir / "d.csv.progress"));
}

TEST(CollectCli, BadOptionsGiveOneLineAndNoOutput) {
  const test_support::ScratchDir scratch("onetip-collect");
  const auto dir = scratch.path();
  const std::string out = (dir / "d.csv").string();
  const std::vector<std::vector<std::string>> bad = {
      {"--out", out, "--step", "0"},          {"--out", out, "--step", "abc"},
      {"--out", out, "--sensor", "glove"},    {"--out", (dir / "d.txt").string()},
      {"--out", out, "--max-rows", "-5"},     {"--step", "30"},
      {"--out", out, "--sensor", "onetip", "--noise", "2"}};
  for (const auto& args : bad) {
    const Exit e = runCli(args, dir);
    EXPECT_EQ(e.status, 2) << args[1];
    EXPECT_EQ(std::count(e.stderr_text.begin(), e.stderr_text.end(), '\n'), 1) << e.stderr_text;
    EXPECT_EQ(e.stderr_text.rfind("onetip collect: ", 0), 0u) << e.stderr_text;
    EXPECT_FALSE(fs::exists(dir / "d.csv"));
    EXPECT_FALSE(fs::exists(dir / "d.csv.progress"));
    EXPECT_FALSE(fs::exists(dir / "d.txt.progress"));
  }
}
