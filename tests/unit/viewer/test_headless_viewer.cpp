// The viewer headless (EGL, llvmpipe here) on a simulated touch: each panel
// shows something and changes as the finger moves — image statistics in the
// panels' regions at two frames, not a golden image.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "core/error.hpp"
#include "pipeline/frame_processor.hpp"
#include "viewer/field_geometry.hpp"
#include "viewer/panel_layout.hpp"
#include "viewer/viewer_session.hpp"
#include "viewer/virtual_finger.hpp"
#include "test_paths.hpp"

namespace onetip::viewer {
namespace {

const std::string kDemo = std::string("sim:") + onetip::test::sourceDir() + "/samples/scenarios/demo_touch.yaml";

// Pixels within `tolerance` (per channel, 0-255) of a colour.
int pixelsNear(const cv::Mat& bgr, const Rgba& c, int tolerance) {
  const cv::Scalar bgr_c(c[2] * 255.0, c[1] * 255.0, c[0] * 255.0);
  cv::Mat mask;
  cv::inRange(bgr, bgr_c - cv::Scalar::all(tolerance), bgr_c + cv::Scalar::all(tolerance), mask);
  return cv::countNonZero(mask);
}

double spread(const cv::Mat& bgr) {
  cv::Mat grey;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  cv::Scalar mean, sd;
  cv::meanStdDev(grey, mean, sd);
  return sd[0];
}

double meanAbsDiff(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat d;
  cv::absdiff(a, b, d);
  const cv::Scalar m = cv::mean(d);
  return (m[0] + m[1] + m[2]) / 3.0;
}

TEST(HeadlessViewer, EveryPanelShowsTheTouchAndChangesAsTheFingerMoves) {
  ViewerOptions o;
  o.input = kDemo;
  o.frames = 36;  // rest at frame 0; pressed 1.5 mm and sliding by frame 35 (t = 1.17 s)
  o.headless = true;
  cv::Mat rest, next_rest, pressed;
  bool pressed_in_contact = false;
  double pressed_dz = 0;
  const ViewerReport r = runViewer(o, [&](const cv::Mat& bgr, const ViewerFrame& f) {
    if (f.index == 0) rest = bgr.clone();
    if (f.index == 1) next_rest = bgr.clone();
    if (f.index == 35) {
      pressed = bgr.clone();
      pressed_in_contact = f.result.pose.contact;
      pressed_dz = f.result.pose.raw.dz;
    }
  });
  ASSERT_EQ(r.drawn, 36);
  EXPECT_NE(r.gl.find("Core Profile"), std::string::npos) << r.gl;
  ASSERT_FALSE(rest.empty());
  ASSERT_FALSE(pressed.empty());
  ASSERT_TRUE(pressed_in_contact);
  EXPECT_GT(pressed_dz, 1.0);
  ASSERT_EQ(pressed.size(), cv::Size(1280, 720));

  const PanelLayout layout = PanelLayout::forWindow(pressed.size());
  for (const auto& [name, rect] : layout.panels()) {
    const double moving = meanAbsDiff(rest(rect), pressed(rect));
    const double still = meanAbsDiff(rest(rect), next_rest(rect));
    SCOPED_TRACE(std::string(name) + ": change " + std::to_string(moving) + " vs " + std::to_string(still) +
                 " between two rest frames");
    EXPECT_GT(spread(pressed(rect)), 10.0);  // not blank
    EXPECT_GT(spread(rest(rect)), 8.0);
    EXPECT_GT(moving, 0.5);  // the panel changes
    // The finger's panels change with the touch, not just with noise or text
    // (timings change every frame whatever the finger does).
    if (name != "timing") {
      EXPECT_GT(moving, 2.0 * still);
    }
    std::printf("panel %-8s spread %5.1f  change rest->pressed %6.2f  rest->rest %6.2f\n", std::string(name).c_str(),
                spread(pressed(rect)), moving, still);
  }
  // The contact map shows stick (or slip) markers only once the finger touches.
  const int labelled_rest = pixelsNear(rest(layout.contact), stickColour(), 30) +
                            pixelsNear(rest(layout.contact), slipColour(), 30);
  const int labelled_pressed = pixelsNear(pressed(layout.contact), stickColour(), 30) +
                               pixelsNear(pressed(layout.contact), slipColour(), 30);
  EXPECT_EQ(labelled_rest, 0);
  EXPECT_GT(labelled_pressed, 200);
  // The field is coloured warmer (red-yellow) where it is pressed.
  auto warm = [](const cv::Mat& bgr) {
    cv::Mat mask;
    cv::inRange(bgr, cv::Scalar(0, 80, 150), cv::Scalar(90, 255, 255), mask);
    return cv::countNonZero(mask);
  };
  EXPECT_GT(warm(pressed(layout.field)), warm(rest(layout.field)) + 500);
}

TEST(VirtualFingerSource, PressAndSlideAreSeenByThePipeline) {
  VirtualFingerSource source;
  pipeline::FrameProcessor processor(source.simulator().calibration(), source.simulator().pattern());
  FingerControls press;
  press.press = 0.25;
  FingerControls slide;
  slide.slide_x = 0.1;
  pipeline::FrameResult r;
  for (int k = 0; k < 24; ++k) {
    if (k > 0) source.finger().apply(k < 12 ? press : slide);  // 2.25 mm deep, then 1.2 mm along S.x
    const capture::Frame f = source.next();
    ASSERT_TRUE(f.ok());
    r = processor.process(f.grey, f.timestamp_s);
    ASSERT_NE(r.status, pipeline::FrameStatus::lost) << "frame " << k << ": " << r.message;
  }
  const sim::GroundTruthFrame& truth = source.simulator().current();
  EXPECT_DOUBLE_EQ(source.finger().pose().depth, 2.25);
  EXPECT_DOUBLE_EQ(source.finger().pose().x, 1.2);
  ASSERT_TRUE(truth.in_contact);
  ASSERT_TRUE(r.pose.contact);
  EXPECT_NEAR(r.pose.raw.dz, truth.input.dz, 0.3);
  EXPECT_NEAR(r.pose.raw.dx, truth.input.dx, 0.3);
  EXPECT_GT(r.pose.raw.dx, 0.3);  // the slide shows (partly absorbed by the pad's stick region)
}

TEST(HeadlessViewer, RecordsWhatItShowsAsPngsAndVideo) {
  const auto dir = std::filesystem::temp_directory_path() / ("onetip_view_rec_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  ViewerOptions o;
  o.input = kDemo;
  o.frames = 3;
  o.headless = true;
  o.window = {640, 360};
  o.record = (dir / "pngs").string();
  std::vector<cv::Mat> shown;
  runViewer(o, [&](const cv::Mat& bgr, const ViewerFrame&) { shown.push_back(bgr.clone()); });
  ASSERT_EQ(shown.size(), 3U);
  for (int i = 0; i < 3; ++i) {
    const cv::Mat png = cv::imread((dir / "pngs" / ("frame_00000" + std::to_string(i) + ".png")).string());
    ASSERT_FALSE(png.empty()) << i;
    EXPECT_EQ(cv::norm(png, shown[static_cast<size_t>(i)], cv::NORM_INF), 0.0) << i;
  }
  o.record = (dir / "view.mp4").string();
  runViewer(o);
  cv::VideoCapture video(o.record);
  ASSERT_TRUE(video.isOpened());
  EXPECT_EQ(static_cast<int>(video.get(cv::CAP_PROP_FRAME_COUNT)), 3);
  EXPECT_EQ(static_cast<int>(video.get(cv::CAP_PROP_FRAME_WIDTH)), 640);
  for (const auto& e : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(e.path().string().find(".part"), std::string::npos) << e.path();  // no temporary left
  std::filesystem::remove_all(dir);
}

TEST(HeadlessViewer, BadInputIsAnInputError) {
  ViewerOptions o;
  o.headless = true;
  o.frames = 1;
  o.input = "/nonexistent/frames";
  EXPECT_THROW(runViewer(o), InputError);
  o.input = kDemo;
  o.window = {100, 100};
  EXPECT_THROW(runViewer(o), InputError);
  o.window = {1280, 720};
  o.input = "sim:virtual";
  o.frames = 0;
  EXPECT_THROW(runViewer(o), InputError);  // would never end without a window
}

}  // namespace
}  // namespace onetip::viewer
