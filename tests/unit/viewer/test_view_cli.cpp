// `onetip view` from the command line: headless screenshot, bad input and outputs, frame numbering.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "core/csv_table.hpp"
#include "scratch_dir.hpp"
#include "test_paths.hpp"

namespace {

int run(const std::string& args) {
  return std::system((std::string(onetip::test::cliPath()) + " view " + args + " >/dev/null 2>&1").c_str());
}

TEST(ViewCli, HeadlessScreenshotOfASimulatedPress) {
  const auto png = std::filesystem::temp_directory_path() / ("onetip_view_" + std::to_string(::getpid()) + ".png");
  std::filesystem::remove(png);
  const std::string scenario = std::string(onetip::test::sourceDir()) + "/samples/scenarios/press.yaml";
  ASSERT_EQ(run("--input sim:" + scenario + " --frames 4 --size 960x540 --screenshot " + png.string()), 0);
  const cv::Mat shot = cv::imread(png.string());
  ASSERT_FALSE(shot.empty());
  EXPECT_EQ(shot.size(), cv::Size(960, 540));
  std::filesystem::remove(png);
}

TEST(ViewCli, BadInputExitsNonZeroWithoutAScreenshot) {
  const auto png = std::filesystem::temp_directory_path() / ("onetip_view_bad_" + std::to_string(::getpid()) + ".png");
  EXPECT_NE(run("--input sim:/nonexistent.yaml --frames 2 --screenshot " + png.string()), 0);
  EXPECT_NE(run("--input /nonexistent_folder --frames 2 --screenshot " + png.string()), 0);
  EXPECT_NE(run("--input sim:virtual --size 12by4 --screenshot " + png.string()), 0);
  EXPECT_FALSE(std::filesystem::exists(png));
  // an output that cannot be written is refused before the viewer starts (exit status 2)
  const std::string scenario = std::string(onetip::test::sourceDir()) + "/samples/scenarios/press.yaml";
  EXPECT_EQ(WEXITSTATUS(run("--input sim:" + scenario + " --frames 2 --screenshot /nonexistent_folder/x.png")), 2);
  EXPECT_EQ(WEXITSTATUS(run("--input sim:" + scenario + " --frames 2 --pose-out /nonexistent_folder/p.csv")), 2);
}

// --pose-out numbers frames by their index in the source, as every command does: a folder whose
// frame 1 cannot be read logs frames 0, 2 and 3.
TEST(ViewCli, PoseLogNumbersFramesByTheirIndexInTheSource) {
  const onetip::test_support::ScratchDir dir("onetip-view-cli");
  const std::string scenario = std::string(onetip::test::sourceDir()) + "/samples/scenarios/press.yaml";
  const std::string sim = dir.file("sim");
  ASSERT_EQ(std::system((std::string(onetip::test::cliPath()) + " sim --quiet --frames 4 --scenario " + scenario +
                         " --out " + sim + " >/dev/null 2>&1")
                            .c_str()),
            0);
  std::ofstream(sim + "/frames/000001.png") << "not a png";
  ASSERT_EQ(run("--headless --input " + sim + "/frames --calib " + sim + "/calib.yaml --pattern " + sim +
                "/pattern.yaml --pose-out " + dir.file("pose.csv")),
            0);
  std::vector<std::string> frames;
  for (const auto& row : onetip::readCsv(dir.file("pose.csv")).rows) frames.push_back(row[0]);
  EXPECT_EQ(frames, (std::vector<std::string>{"0", "2", "3"}));
}

}  // namespace
