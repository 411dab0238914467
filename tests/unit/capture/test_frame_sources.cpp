// Folder and video sources, the frame checks, and openFrameSource's specs.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "capture/folder_source.hpp"
#include "capture/open_frame_source.hpp"
#include "core/error.hpp"
#include "scratch_dir.hpp"

namespace onetip::capture {
namespace {

namespace fs = std::filesystem;

cv::Mat pattern(int w, int h, int shade) {
  cv::Mat img(h, w, CV_8UC1, cv::Scalar(shade));
  for (int y = 0; y < h; y += 16)
    for (int x = (y / 16) % 2 * 16; x < w; x += 32)
      cv::rectangle(img, cv::Rect(x, y, 16, 16), cv::Scalar(255 - shade), cv::FILLED);
  return img;
}

void writeBytes(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                              static_cast<std::streamsize>(bytes.size()));
}

TEST(FolderSource, ReadsFramesSortedByNameAndSkipsBadOnes) {
  const onetip::test_support::ScratchDir dir("onetip-capture");
  const cv::Mat a = pattern(96, 64, 10), b = pattern(96, 64, 40), c = pattern(96, 64, 70);
  cv::imwrite(dir.file("frame_002.png"), b);
  cv::imwrite(dir.file("frame_000.png"), a);
  std::vector<std::uint8_t> png;
  cv::imencode(".png", c, png);
  writeBytes(dir.file("frame_001.png"), {png.begin(), png.begin() + static_cast<long>(png.size() / 2)});
  writeBytes(dir.file("frame_003.png"), std::vector<std::uint8_t>(300, 7));   // not a PNG
  cv::imwrite(dir.file("frame_004.png"), pattern(48, 64, 10));               // wrong size
  cv::imwrite(dir.file("frame_005.png"), cv::Mat(64, 96, CV_8UC1, cv::Scalar(128)));  // blank
  cv::Mat colour;
  cv::cvtColor(c, colour, cv::COLOR_GRAY2BGR);
  cv::imwrite(dir.file("frame_006.png"), colour);
  writeBytes(dir.file("notes.txt"), {'h', 'i'});

  FolderSource src(dir.path().string());
  EXPECT_EQ(src.files().size(), 7u);
  Frame f = src.next();
  ASSERT_TRUE(f.ok());
  EXPECT_EQ(f.index, 0);
  EXPECT_EQ(cv::norm(f.grey, a, cv::NORM_INF), 0.0);
  for (int i = 1; i <= 5; ++i) {
    f = src.next();
    if (i == 2) {  // frame_002 is good
      ASSERT_TRUE(f.ok()) << f.message;
      EXPECT_EQ(cv::norm(f.grey, b, cv::NORM_INF), 0.0);
      continue;
    }
    EXPECT_EQ(f.status, FrameStatus::skipped) << i;
    EXPECT_EQ(f.index, i);
    EXPECT_NE(f.message.find("frame_00" + std::to_string(i)), std::string::npos) << f.message;
  }
  f = src.next();
  ASSERT_TRUE(f.ok()) << f.message;  // colour converted to grey
  EXPECT_EQ(f.index, 6);
  EXPECT_NEAR(f.timestamp_s, 6.0 / 30.0, 1e-12);
  EXPECT_EQ(cv::norm(f.grey, c, cv::NORM_INF), 0.0);
  EXPECT_EQ(src.next().status, FrameStatus::end);
  EXPECT_EQ(src.next().status, FrameStatus::end);
  EXPECT_EQ(src.counters().delivered, 3);
  EXPECT_EQ(src.counters().skipped, 4);
}

TEST(FolderSource, OneFrameIsAValidStream) {
  const onetip::test_support::ScratchDir dir("onetip-capture");
  cv::imwrite(dir.file("only.png"), pattern(32, 32, 0));
  auto src = openFrameSource(dir.path().string());
  EXPECT_TRUE(src->next().ok());
  EXPECT_EQ(src->next().status, FrameStatus::end);
}

TEST(FolderSource, MissingOrEmptyFolderIsAnInputError) {
  const onetip::test_support::ScratchDir dir("onetip-capture");
  EXPECT_THROW(FolderSource(dir.path().string()), InputError);  // no images
  EXPECT_THROW(FolderSource(dir.file("missing")), InputError);
}

TEST(VideoSource, ReadsAVideoFileAsGreyFrames) {
  const onetip::test_support::ScratchDir dir("onetip-capture");
  const std::string path = dir.file("clip.avi");
  {
    cv::VideoWriter w(path, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25.0, cv::Size(96, 64), false);
    ASSERT_TRUE(w.isOpened()) << "no MJPG video writer in this OpenCV";
    for (int i = 0; i < 4; ++i) w.write(pattern(96, 64, 20 * i));
  }
  auto src = openFrameSource(path);
  for (int i = 0; i < 4; ++i) {
    const Frame f = src->next();
    ASSERT_TRUE(f.ok()) << f.message;
    EXPECT_EQ(f.index, i);
    EXPECT_EQ(f.grey.type(), CV_8UC1);
    EXPECT_NEAR(f.timestamp_s, i / 25.0, 1e-3);
    EXPECT_LT(cv::norm(f.grey, pattern(96, 64, 20 * i), cv::NORM_L1) / (96 * 64), 3.0);
  }
  EXPECT_EQ(src->next().status, FrameStatus::end);
}

TEST(OpenFrameSource, SchemesPathsAndErrors) {
  EXPECT_THROW(openFrameSource(""), InputError);
  EXPECT_THROW(openFrameSource("/nonexistent/frames"), InputError);
  EXPECT_THROW(openFrameSource("nosuchscheme:foo.yaml"), InputError);
  const onetip::test_support::ScratchDir dir("onetip-capture");
  writeBytes(dir.file("not_a_video.avi"), std::vector<std::uint8_t>(100, 1));
  EXPECT_THROW(openFrameSource(dir.file("not_a_video.avi")), InputError);

  struct Fixed : FrameSource {
    std::string rest;
    explicit Fixed(std::string r) : rest(std::move(r)) {}
    Frame next() override { return Frame{}; }
    std::string describe() const override { return rest; }
  };
  registerFrameSourceScheme("testscheme", [](const std::string& rest) {
    return std::make_unique<Fixed>(rest);
  });
  EXPECT_EQ(openFrameSource("testscheme:a/b:c.yaml")->describe(), "a/b:c.yaml");
  EXPECT_THROW(registerFrameSourceScheme("a", nullptr), InputError);
}

TEST(FrameChecker, OptionsAreValidated) {
  FrameCheckOptions o;
  o.min_stddev = -1;
  EXPECT_THROW(o.validate(), InputError);
  o = {};
  o.expected_size = {10, 0};
  EXPECT_THROW(o.validate(), InputError);
}

}  // namespace
}  // namespace onetip::capture
