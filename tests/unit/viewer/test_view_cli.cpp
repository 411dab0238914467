// `onetip view` from the command line: headless screenshot, bad input.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <string>
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
}

}  // namespace
