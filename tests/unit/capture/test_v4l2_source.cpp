// V4L2 capture against a simulated device (fake_v4l2_device.hpp): format
// choice, negotiation, decoding of recorded payloads, driver timestamps,
// corrupted frames, unplug / reconnect, time-out and clean stop.
#include <gtest/gtest.h>
#include <linux/videodev2.h>

#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "capture/v4l2_format.hpp"
#include "capture/session_source.hpp"
#include "capture/session_writer.hpp"
#include "capture/v4l2_source.hpp"
#include "core/error.hpp"
#include "fake_v4l2_device.hpp"
#include "scratch_dir.hpp"

namespace onetip::capture {
namespace {

using testing::FakePayload;
using testing::FakeV4l2Device;

constexpr std::uint32_t kMjpg = V4L2_PIX_FMT_MJPEG;
constexpr std::uint32_t kYuyv = V4L2_PIX_FMT_YUYV;
constexpr std::uint32_t kGrey = V4L2_PIX_FMT_GREY;

V4l2FormatOffer offer(std::uint32_t f, int w, int h, std::uint32_t fps) {
  return {f, w, h, 1, fps};
}

TEST(V4l2FormatChoice, PrefersRequestedSizeThenRateThenUncompressed) {
  V4l2FormatRequest want;  // 1920x1080
  // 1080p only as MJPEG at 30 and YUYV at 5: the rate decides (MJPEG 30).
  auto c = chooseV4l2Format({offer(kYuyv, 1920, 1080, 5), offer(kMjpg, 1920, 1080, 30),
                             offer(kYuyv, 640, 480, 60), offer(kMjpg, 1280, 720, 60)},
                            want);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->fourcc, kMjpg);
  EXPECT_EQ(c->width, 1920);
  EXPECT_DOUBLE_EQ(c->fps(), 30.0);
  // Equal size and rate: uncompressed GREY, then YUYV, before MJPEG.
  c = chooseV4l2Format({offer(kMjpg, 1920, 1080, 30), offer(kYuyv, 1920, 1080, 30)}, want);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->fourcc, kYuyv);
  c = chooseV4l2Format({offer(kYuyv, 1920, 1080, 30), offer(kGrey, 1920, 1080, 30)}, want);
  EXPECT_EQ(c->fourcc, kGrey);
  // No 1080p: the closest area wins over a higher rate at a far size.
  c = chooseV4l2Format({offer(kMjpg, 640, 480, 120), offer(kMjpg, 2048, 1080, 15),
                        offer(kMjpg, 1280, 720, 30)},
                       want);
  EXPECT_EQ(c->width, 2048);
  // Formats we cannot decode never win; nothing decodable -> nothing.
  EXPECT_FALSE(chooseV4l2Format({offer(V4L2_PIX_FMT_H264, 1920, 1080, 60)}, want));
  // A caller's preference order is honoured.
  want.preferred = {kMjpg, kYuyv};
  c = chooseV4l2Format({offer(kYuyv, 1920, 1080, 30), offer(kMjpg, 1920, 1080, 30)}, want);
  EXPECT_EQ(c->fourcc, kMjpg);
}

cv::Mat testImage(int w, int h, int seed) {
  cv::Mat img(h, w, CV_8UC1);
  cv::RNG rng(static_cast<std::uint64_t>(seed));
  rng.fill(img, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(img, img, cv::Size(5, 5), 1.5);
  cv::rectangle(img, cv::Rect(w / 4, h / 4, w / 2, h / 2), cv::Scalar(250), cv::FILLED);
  return img;
}

std::vector<std::uint8_t> jpegOf(const cv::Mat& img) {
  std::vector<std::uint8_t> out;
  cv::imencode(".jpg", img, out, {cv::IMWRITE_JPEG_QUALITY, 95});
  return out;
}

std::vector<std::uint8_t> yuyvOf(const cv::Mat& grey, std::size_t padding) {
  const std::size_t line = static_cast<std::size_t>(grey.cols) * 2 + padding;
  std::vector<std::uint8_t> out(line * static_cast<std::size_t>(grey.rows), 0);
  for (int y = 0; y < grey.rows; ++y)
    for (int x = 0; x < grey.cols; ++x) {
      out[line * static_cast<std::size_t>(y) + 2 * static_cast<std::size_t>(x)] = grey.at<std::uint8_t>(y, x);
      out[line * static_cast<std::size_t>(y) + 2 * static_cast<std::size_t>(x) + 1] =
          static_cast<std::uint8_t>(37 * x + y);  // chroma must not leak into grey
    }
  return out;
}

V4l2SourceOptions smallOptions() {
  V4l2SourceOptions o;
  o.format.width = 320;
  o.format.height = 240;
  o.frame_timeout_ms = 30;
  o.reconnect_interval_s = 0.001;
  o.max_reconnect_attempts = 3;
  return o;
}

TEST(V4l2Source, NegotiatesAndDecodesMjpegWithDriverTimestamps) {
  auto dev = std::make_shared<FakeV4l2Device>();
  dev->modes = {{kYuyv, 320, 240, {10}}, {kMjpg, 320, 240, {15, 30}}, {kMjpg, 160, 120, {60}}};
  const cv::Mat a = testImage(320, 240, 1), b = testImage(320, 240, 2);
  dev->payloads.push_back({jpegOf(a), 0, 100.25});
  dev->payloads.push_back({jpegOf(b), 0, 100.2834});
  {
    V4l2Source src("/dev/video0", smallOptions(), dev);
    EXPECT_EQ(src.format().fourcc, kMjpg);  // 30 Hz beats YUYV's 10 Hz
    EXPECT_EQ(dev->set_fourcc, kMjpg);
    EXPECT_EQ(dev->set_interval_den, 30u);
    EXPECT_TRUE(dev->streaming);
    const Frame f0 = src.next(), f1 = src.next();
    ASSERT_TRUE(f0.ok()) << f0.message;
    ASSERT_TRUE(f1.ok()) << f1.message;
    EXPECT_EQ(f0.index, 0);
    EXPECT_EQ(f1.index, 1);
    EXPECT_NEAR(f0.timestamp_s, 100.25, 1e-6);
    EXPECT_NEAR(f1.timestamp_s, 100.2834, 1e-6);
    // Reference decoder: OpenCV's own JPEG reader.
    const cv::Mat ref = cv::imdecode(jpegOf(b), cv::IMREAD_GRAYSCALE);
    EXPECT_LE(cv::norm(f1.grey, ref, cv::NORM_INF), 1.0);
  }
  // Clean stop: stream off, buffers unmapped, device closed.
  EXPECT_FALSE(dev->streaming);
  EXPECT_EQ(dev->mapped, 0);
  EXPECT_FALSE(dev->openFd());
}

TEST(V4l2Source, DecodesYuyvWithPaddedLines) {
  auto dev = std::make_shared<FakeV4l2Device>();
  dev->modes = {{kYuyv, 320, 240, {30}}};
  dev->line_padding = 64;
  const cv::Mat a = testImage(320, 240, 3);
  dev->payloads.push_back({yuyvOf(a, 64), 0, 1.0});
  V4l2Source src("/dev/video0", smallOptions(), dev);
  const Frame f = src.next();
  ASSERT_TRUE(f.ok()) << f.message;
  EXPECT_EQ(cv::norm(f.grey, a, cv::NORM_INF), 0.0);
}

TEST(V4l2Source, BadFramesAreCountedSkipsAndTheStreamGoesOn) {
  auto dev = std::make_shared<FakeV4l2Device>();
  dev->modes = {{kMjpg, 320, 240, {30}}};
  const auto good = jpegOf(testImage(320, 240, 4));
  auto truncated = good;
  truncated.resize(good.size() / 3);
  dev->payloads.push_back({good, V4L2_BUF_FLAG_ERROR, 1.0});                 // driver error
  dev->payloads.push_back({truncated, 0, 2.0});                               // truncated
  dev->payloads.push_back({std::vector<std::uint8_t>(5000, 0x55), 0, 3.0});  // garbage
  dev->payloads.push_back({jpegOf(testImage(160, 120, 5)), 0, 4.0});         // wrong size
  dev->payloads.push_back({jpegOf(cv::Mat(240, 320, CV_8UC1, cv::Scalar(0))), 0, 5.0});  // blank
  dev->payloads.push_back({good, 0, 6.0});
  V4l2Source src("/dev/video0", smallOptions(), dev);
  for (int i = 0; i < 5; ++i) {
    const Frame f = src.next();
    EXPECT_EQ(f.status, FrameStatus::skipped) << i;
    EXPECT_FALSE(f.message.empty());
    EXPECT_TRUE(f.grey.empty());
  }
  const Frame f = src.next();
  ASSERT_TRUE(f.ok()) << f.message;
  EXPECT_EQ(f.index, 5);
  EXPECT_EQ(src.counters().skipped, 5);
  EXPECT_EQ(src.counters().delivered, 1);
}

TEST(V4l2Source, UnplugBecomesErrorEventThenReconnects) {
  auto dev = std::make_shared<FakeV4l2Device>();
  dev->modes = {{kMjpg, 320, 240, {30}}};
  const auto good = jpegOf(testImage(320, 240, 6));
  dev->payloads.push_back({good, 0, 1.0});
  V4l2Source src("/dev/video0", smallOptions(), dev);
  ASSERT_TRUE(src.next().ok());
  dev->present = false;  // cable pulled
  Frame f = src.next();
  EXPECT_EQ(f.status, FrameStatus::error);
  EXPECT_NE(f.message.find("reconnecting"), std::string::npos) << f.message;
  EXPECT_FALSE(src.streaming());
  EXPECT_EQ(dev->mapped, 0);
  f = src.next();  // reopen fails while unplugged
  EXPECT_EQ(f.status, FrameStatus::error);
  dev->present = true;  // plugged back in
  dev->payloads.push_back({good, 0, 2.0});
  f = src.next();
  ASSERT_TRUE(f.ok()) << f.message;
  EXPECT_NEAR(f.timestamp_s, 2.0, 1e-6);
  EXPECT_EQ(dev->streamon_count, 2);
  EXPECT_EQ(src.counters().errors, 2);
}

TEST(V4l2Source, GivesUpAfterTheReconnectLimitAndTimesOutInsteadOfHanging) {
  auto dev = std::make_shared<FakeV4l2Device>();
  dev->modes = {{kGrey, 320, 240, {30}}};
  V4l2Source src("/dev/video0", smallOptions(), dev);
  Frame f = src.next();  // no payload: time-out after 30 ms, not a hang
  EXPECT_EQ(f.status, FrameStatus::error);
  EXPECT_NE(f.message.find("no frame within"), std::string::npos) << f.message;
  dev->present = false;
  int events = 0;
  while ((f = src.next()).status == FrameStatus::error) ASSERT_LT(++events, 10);
  EXPECT_EQ(f.status, FrameStatus::end);
  EXPECT_EQ(events, 2);  // attempts 1 and 2 are events; attempt 3 ends the stream
  EXPECT_EQ(src.next().status, FrameStatus::end);
}

TEST(V4l2Source, UnusableDevicesAreInputErrors) {
  auto missing = std::make_shared<FakeV4l2Device>();
  missing->present = false;
  EXPECT_THROW(V4l2Source("/dev/video9", smallOptions(), missing), InputError);
  auto no_capture = std::make_shared<FakeV4l2Device>();
  no_capture->modes = {{kMjpg, 320, 240, {30}}};
  no_capture->capabilities = V4L2_CAP_VIDEO_OUTPUT | V4L2_CAP_STREAMING;
  EXPECT_THROW(V4l2Source("/dev/video0", smallOptions(), no_capture), InputError);
  auto h264_only = std::make_shared<FakeV4l2Device>();
  h264_only->modes = {{V4L2_PIX_FMT_H264, 320, 240, {30}}};
  try {
    V4l2Source src("/dev/video0", smallOptions(), h264_only);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("MJPEG"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(h264_only->openFd());  // the failed start closed the device
  // Only a real device node path reaches the system layer: none exists here.
  EXPECT_THROW(V4l2Source("/nonexistent/video0"), InputError);
}

// Record and replay (issue 17): a camera's MJPEG bytes are kept as delivered,
// and the session replays the same grey frames, indices and timestamps.
TEST(V4l2Source, MjpegIsRecordedAsDeliveredAndReplaysIdentically) {
  auto dev = std::make_shared<FakeV4l2Device>();
  dev->modes = {{kMjpg, 320, 240, {30}}};
  const std::vector<std::uint8_t> a = jpegOf(testImage(320, 240, 11)), b = jpegOf(testImage(320, 240, 12));
  dev->payloads.push_back({a, 0, 10.125});
  dev->payloads.push_back({std::vector<std::uint8_t>(a.begin(), a.begin() + 100), 0, 10.158});  // truncated
  dev->payloads.push_back({b, 0, 10.191666666666666});
  const test_support::ScratchDir dir("onetip-session-mjpeg");
  std::vector<Frame> live;
  std::string statuses;
  {
    V4l2Source src("/dev/video0", smallOptions(), dev);
    ASSERT_TRUE(src.keepEncodedFrames(true));
    SessionWriter writer(dir.path().string());
    for (int i = 0; i < 3; ++i) {
      Frame f = src.next();
      statuses += std::string(toString(f.status)) + " " + f.message + "; ";
      if (!f.ok()) {
        EXPECT_TRUE(f.encoded.empty());
        continue;
      }
      writer.add(f);
      live.push_back(std::move(f));
    }
    writer.finish();
  }
  ASSERT_EQ(live.size(), 2u) << statuses;
  EXPECT_EQ(live[0].encoded, a);
  EXPECT_EQ(live[1].encoded, b);
  std::ifstream in(dir.path() / "frames/000000.jpg", std::ios::binary);
  EXPECT_EQ(std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), {}), a);  // not re-encoded
  SessionSource replay(dir.path().string());
  for (const Frame& l : live) {
    const Frame r = replay.next();
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_EQ(r.index, l.index);
    EXPECT_EQ(r.timestamp_s, l.timestamp_s);
    EXPECT_EQ(cv::norm(r.grey, l.grey, cv::NORM_INF), 0.0);
  }
  EXPECT_EQ(replay.next().status, FrameStatus::end);
  EXPECT_EQ(live[1].index, 2);  // the skipped frame keeps its place in the numbering
}

TEST(V4l2Source, UncompressedModesHaveNoEncodedFramesToKeep) {
  auto dev = std::make_shared<FakeV4l2Device>();
  dev->modes = {{kYuyv, 320, 240, {30}}};
  V4l2Source src("/dev/video0", smallOptions(), dev);
  EXPECT_FALSE(src.keepEncodedFrames(true));
  EXPECT_TRUE(src.keepEncodedFrames(false));
}

}  // namespace
}  // namespace onetip::capture
