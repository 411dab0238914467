// Camera payload decoding on recorded bytes: YUYV and GREY with line
// strides, MJPEG through TurboJPEG against OpenCV's decoder, and the
// failures (truncated, corrupt, wrong size) that must not produce an image.
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "capture/jpeg_grey_decoder.hpp"
#include "capture/raw_decode.hpp"

namespace onetip::capture {
namespace {

cv::Mat texture(int w, int h) {
  cv::Mat img(h, w, CV_8UC1);
  cv::randu(img, 0, 256);
  cv::GaussianBlur(img, img, cv::Size(7, 7), 2.0);
  return img;
}

TEST(RawDecode, YuyvKeepsLumaOnlyAndHonoursTheStride) {
  const cv::Mat grey = texture(64, 48);
  const std::size_t stride = 64 * 2 + 16;
  std::vector<std::uint8_t> bytes(stride * 48, 0xAB);
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) {
      bytes[stride * static_cast<std::size_t>(y) + 2 * static_cast<std::size_t>(x)] = grey.at<std::uint8_t>(y, x);
      bytes[stride * static_cast<std::size_t>(y) + 2 * static_cast<std::size_t>(x) + 1] =
          static_cast<std::uint8_t>(x * 3 + y);
    }
  cv::Mat out;
  ASSERT_TRUE(yuyvToGrey(bytes.data(), bytes.size(), 64, 48, stride, out).ok);
  EXPECT_EQ(cv::norm(out, grey, cv::NORM_INF), 0.0);
  // The last line needs no padding; one byte less than the pixels is truncated.
  const std::size_t minimal = stride * 47 + 128;
  EXPECT_TRUE(yuyvToGrey(bytes.data(), minimal, 64, 48, stride, out).ok);
  const DecodeResult r = yuyvToGrey(bytes.data(), minimal - 1, 64, 48, stride, out);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.message.find("truncated"), std::string::npos);
  EXPECT_FALSE(yuyvToGrey(bytes.data(), bytes.size(), 64, 48, 100, out).ok);  // stride < line
}

TEST(RawDecode, GreyCopiesRowsAcrossTheStride) {
  const cv::Mat grey = texture(50, 20);
  const std::size_t stride = 64;
  std::vector<std::uint8_t> bytes(stride * 20, 0);
  for (int y = 0; y < 20; ++y)
    std::memcpy(bytes.data() + stride * static_cast<std::size_t>(y), grey.ptr(y), 50);
  cv::Mat out;
  ASSERT_TRUE(greyToGrey(bytes.data(), bytes.size(), 50, 20, stride, out).ok);
  EXPECT_EQ(cv::norm(out, grey, cv::NORM_INF), 0.0);
  EXPECT_FALSE(greyToGrey(bytes.data(), 10, 50, 20, stride, out).ok);
}

std::vector<std::uint8_t> encode(const cv::Mat& img, int quality = 92) {
  std::vector<std::uint8_t> out;
  cv::imencode(".jpg", img, out, {cv::IMWRITE_JPEG_QUALITY, quality});
  return out;
}

TEST(JpegGreyDecoder, MatchesOpenCvOnGreyAndColourJpegs) {
  JpegGreyDecoder decoder;
  const cv::Mat grey = texture(320, 200);
  cv::Mat colour;
  cv::merge(std::vector<cv::Mat>{grey, texture(320, 200), 255 - grey}, colour);
  for (const cv::Mat& img : {grey, colour}) {
    const auto jpeg = encode(img);
    cv::Mat ours;
    const DecodeResult r = decoder.decode(jpeg.data(), jpeg.size(), {320, 200}, ours);
    ASSERT_TRUE(r.ok) << r.message;
    const cv::Mat ref = cv::imdecode(jpeg, cv::IMREAD_GRAYSCALE);
    ASSERT_EQ(ours.size(), ref.size());
    // Same luma plane; OpenCV converts colour to grey itself, so allow 1 level.
    EXPECT_LE(cv::norm(ours, ref, cv::NORM_INF), 1.0);
  }
}

// Many webcams send Motion-JPEG frames without Huffman tables (DHT).
TEST(JpegGreyDecoder, DecodesMotionJpegWithoutHuffmanTables) {
  const cv::Mat grey = texture(160, 120);
  const auto jpeg = encode(grey);
  std::vector<std::uint8_t> mjpeg;
  std::size_t i = 0, removed = 0;
  while (i + 4 <= jpeg.size()) {
    if (jpeg[i] == 0xFF && jpeg[i + 1] == 0xDA) break;  // start of scan: copy the rest
    if (jpeg[i] == 0xFF && jpeg[i + 1] == 0xC4) {       // DHT segment: drop it
      const std::size_t len = static_cast<std::size_t>(jpeg[i + 2] << 8 | jpeg[i + 3]);
      i += 2 + len;
      ++removed;
      continue;
    }
    const bool standalone = jpeg[i + 1] == 0xD8;
    const std::size_t len = standalone ? 0 : static_cast<std::size_t>(jpeg[i + 2] << 8 | jpeg[i + 3]);
    mjpeg.insert(mjpeg.end(), jpeg.begin() + static_cast<long>(i),
                 jpeg.begin() + static_cast<long>(i + 2 + len));
    i += 2 + len;
  }
  mjpeg.insert(mjpeg.end(), jpeg.begin() + static_cast<long>(i), jpeg.end());
  ASSERT_GT(removed, 0u);
  JpegGreyDecoder decoder;
  cv::Mat ours;
  const DecodeResult r = decoder.decode(mjpeg.data(), mjpeg.size(), {160, 120}, ours);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(cv::norm(ours, cv::imdecode(jpeg, cv::IMREAD_GRAYSCALE), cv::NORM_INF), 0.0);
}

TEST(JpegGreyDecoder, RejectsTruncatedCorruptAndWrongSizeFrames) {
  JpegGreyDecoder decoder;
  const auto jpeg = encode(texture(320, 200));
  cv::Mat out;
  auto truncated = jpeg;
  truncated.resize(jpeg.size() / 2);
  EXPECT_FALSE(decoder.decode(truncated.data(), truncated.size(), {320, 200}, out).ok);
  EXPECT_TRUE(out.empty());
  std::vector<std::uint8_t> garbage(4000);
  cv::randu(garbage, 0, 256);
  EXPECT_FALSE(decoder.decode(garbage.data(), garbage.size(), {320, 200}, out).ok);
  const DecodeResult wrong = decoder.decode(jpeg.data(), jpeg.size(), {640, 480}, out);
  EXPECT_FALSE(wrong.ok);
  EXPECT_NE(wrong.message.find("320x200"), std::string::npos) << wrong.message;
  EXPECT_FALSE(decoder.decode(jpeg.data(), 2, {320, 200}, out).ok);
  EXPECT_TRUE(out.empty());
  // The decoder is still usable after failures.
  EXPECT_TRUE(decoder.decode(jpeg.data(), jpeg.size(), {0, 0}, out).ok);
  EXPECT_EQ(out.size(), cv::Size(320, 200));
}

TEST(JpegGreyDecoder, AFrameCutInsideItsHeaderDoesNotSpoilTheNext) {
  // TurboJPEG's handle used to report 0x0 for the valid frame after a failed header read
  JpegGreyDecoder decoder;
  const auto jpeg = encode(texture(320, 200));
  const std::vector<std::uint8_t> cut(jpeg.begin(), jpeg.begin() + 100);
  cv::Mat out;
  for (int i = 0; i < 3; ++i) {
    EXPECT_FALSE(decoder.decode(cut.data(), cut.size(), {320, 200}, out).ok);
    const DecodeResult next = decoder.decode(jpeg.data(), jpeg.size(), {320, 200}, out);
    EXPECT_TRUE(next.ok) << next.message;
    EXPECT_EQ(out.size(), cv::Size(320, 200));
  }
}

}  // namespace
}  // namespace onetip::capture
