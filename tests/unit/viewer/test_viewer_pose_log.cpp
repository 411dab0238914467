// `onetip view --pose-out`: the log holds, per drawn frame, the 6-D input the
// viewer showed and — for simulated inputs — the ground truth of an
// independently played simulator; bad window options are input errors.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/csv_table.hpp"
#include "core/error.hpp"
#include "sim/simulator.hpp"
#include "viewer/viewer_session.hpp"
#include "test_paths.hpp"

namespace onetip::viewer {
namespace {

const std::string kDemoPath = std::string(onetip::test::sourceDir()) + "/samples/scenarios/demo_touch.yaml";

std::string tempCsv(const std::string& name) {
  return (std::filesystem::temp_directory_path() / (name + std::to_string(::getpid()) + ".csv")).string();
}

TEST(ViewerPoseLog, HoldsWhatWasShownAndTheSimulatorsGroundTruth) {
  ViewerOptions o;
  o.input = "sim:" + kDemoPath;
  o.frames = 36;
  o.headless = true;
  o.window = {640, 360};
  o.pose_out = tempCsv("onetip_view_pose_");
  std::vector<Input6> shown, shown_sd;
  runViewer(o, [&](const cv::Mat&, const ViewerFrame& f) {
    shown.push_back(f.result.pose.raw);
    shown_sd.push_back(f.result.pose.sd);
  });
  const CsvTable log = readCsv(o.pose_out);
  std::filesystem::remove(o.pose_out);
  ASSERT_EQ(log.rows.size(), 36U);
  ASSERT_EQ(log.header.size(), 22U);  // pose.csv's 15 columns and 7 of ground truth
  EXPECT_EQ(log.header[8], "roll");
  EXPECT_EQ(log.header[9], "sd_dx");
  EXPECT_EQ(log.header[14], "sd_roll");
  EXPECT_EQ(log.header[21], "gt_roll");

  sim::Simulator truth(sim::loadScenario(kDemoPath));  // played again, on its own
  for (size_t k = 0; k < log.rows.size(); ++k) {
    const sim::GroundTruthFrame& g = truth.next();
    const auto cell = [&](const char* name) { return parseNumber(log.rows[k][log.column(name, "log")], name); };
    SCOPED_TRACE("frame " + std::to_string(k));
    EXPECT_EQ(cell("frame"), g.index);
    EXPECT_EQ(cell("gt_contact"), g.in_contact ? 1 : 0);
    EXPECT_NEAR(cell("gt_dz"), g.input.dz, 1e-6);
    EXPECT_NEAR(cell("gt_dx"), g.input.dx, 1e-6);
    EXPECT_NEAR(cell("gt_yaw"), g.input.yaw, 1e-6);
    EXPECT_NEAR(cell("dz"), shown[k].dz, 1e-6);
    EXPECT_NEAR(cell("dx"), shown[k].dx, 1e-6);
    EXPECT_NEAR(cell("sd_dz"), shown_sd[k].dz, 1e-6);
    EXPECT_NEAR(cell("sd_yaw"), shown_sd[k].yaw, 1e-6);
    EXPECT_NEAR(cell("dz"), g.input.dz, 0.3);  // the pipeline follows the touch
  }
  EXPECT_GT(parseNumber(log.rows.back()[log.column("gt_dz", "log")], "gt_dz"), 1.0);  // the touch is pressed by then
}

TEST(ViewerPoseLog, TheVirtualFingerAddsItsCommandedPose) {
  ViewerOptions o;
  o.input = "sim:virtual";
  o.frames = 2;
  o.headless = true;
  o.window = {640, 360};
  o.pose_out = tempCsv("onetip_view_finger_");
  runViewer(o);
  const CsvTable log = readCsv(o.pose_out);
  std::filesystem::remove(o.pose_out);
  ASSERT_EQ(log.rows.size(), 2U);
  ASSERT_EQ(log.header.size(), 28U);
  EXPECT_EQ(log.header[22], "finger_x");
  // Untouched controls: the finger rests 0.5 mm above the pad (VirtualFingerOptions).
  EXPECT_DOUBLE_EQ(parseNumber(log.rows[1][log.column("finger_depth", "log")], "finger_depth"), -0.5);
}

// Unsets the display variables for one scope.
class NoDisplay {
 public:
  NoDisplay() {
    for (size_t i = 0; i < kNames.size(); ++i)
      if (const char* v = std::getenv(kNames[i])) saved_[i] = v;
    for (const char* n : kNames) ::unsetenv(n);
  }
  ~NoDisplay() {
    for (size_t i = 0; i < kNames.size(); ++i)
      if (saved_[i]) ::setenv(kNames[i], saved_[i]->c_str(), 1);
  }
  NoDisplay(const NoDisplay&) = delete;
  NoDisplay& operator=(const NoDisplay&) = delete;

 private:
  static constexpr std::array<const char*, 2> kNames{"DISPLAY", "WAYLAND_DISPLAY"};
  std::array<std::optional<std::string>, 2> saved_;
};

TEST(ViewerOptions, AWindowNeedsADisplayAndCannotBeHeadless) {
  ViewerOptions o;
  o.input = "sim:" + kDemoPath;
  o.frames = 1;
  o.windowed = true;
  o.headless = true;
  EXPECT_THROW(o.validate(), InputError);
  o.headless = false;
  const NoDisplay no_display;
  EXPECT_FALSE(displayAvailable());
  EXPECT_THROW(o.validate(), InputError);
  o.windowed = false;
  o.screenshot = "shot.png";
  EXPECT_NO_THROW(o.validate());
  EXPECT_TRUE(o.runsHeadless());
}

}  // namespace
}  // namespace onetip::viewer
