// Image files: the header's declared size is read before decoding and checked
// against the stream's size and a pixel bound (capture/image_file.hpp). Ground
// truth: images encoded here by OpenCV at known sizes, and the hostile corpus
// of tests/hostile/corpus (a 68-byte PNG that claims 40000x40000 pixels, TIFFs
// whose size tags or strip would make OpenCV allocate far beyond the bound).
#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "capture/folder_source.hpp"
#include "capture/image_file.hpp"
#include "input_error_of.hpp"
#include "scratch_dir.hpp"
#include "test_paths.hpp"

namespace {

using namespace onetip;
using namespace onetip::capture;
namespace fs = std::filesystem;

const fs::path kCorpus = fs::path(onetip::test::sourceDir()) / "tests/hostile/corpus";

cv::Mat texture(cv::Size size) {
  cv::Mat m(size, CV_8UC1);
  cv::randu(m, 0, 255);
  return m;
}

TEST(ImageFile, HeaderSizeOfEveryFormatMatchesTheEncodedImage) {
  for (const char* ext : {".png", ".jpg", ".bmp", ".tif"}) {
    for (const cv::Size size : {cv::Size(1, 1), cv::Size(37, 5), cv::Size(640, 481)}) {
      std::vector<std::uint8_t> bytes;
      ASSERT_TRUE(cv::imencode(ext, texture(size), bytes)) << ext;
      const auto declared = declaredImageSize(bytes.data(), bytes.size());
      ASSERT_TRUE(declared.has_value()) << ext;
      EXPECT_EQ(*declared, size) << ext;
    }
  }
  const std::uint8_t text[] = "not an image at all";
  EXPECT_FALSE(declaredImageSize(text, sizeof text).has_value());
  EXPECT_FALSE(declaredImageSize(nullptr, 0).has_value());
}

TEST(ImageFile, DecodesGreyExactlyAfterTheCheck) {
  const cv::Mat grey = texture({320, 200});
  std::vector<std::uint8_t> png;
  ASSERT_TRUE(cv::imencode(".png", grey, png));
  ImageLimits limits;
  limits.expected = grey.size();
  const GreyImage image = decodeGreyImage(png.data(), png.size(), limits);
  ASSERT_FALSE(image.problem) << *image.problem;
  EXPECT_EQ(cv::norm(image.grey, grey, cv::NORM_INF), 0.0);

  limits.expected = {640, 400};  // the stream's size differs: refused from the header alone
  const GreyImage wrong = decodeGreyImage(png.data(), png.size(), limits);
  ASSERT_TRUE(wrong.problem);
  EXPECT_NE(wrong.problem->find("320x200"), std::string::npos) << *wrong.problem;
  EXPECT_TRUE(wrong.grey.empty());
}

// PNG is decoded with libpng (its messages caught), with OpenCV's grey transformations: every layout gives the
// pixels cv::imdecode(IMREAD_GRAYSCALE) gives. OpenCV encodes the common layouts here; tests/data/png holds the
// ones it cannot write (palette with transparency, 2-bit grey and 16-bit RGB interlaced, grey with alpha).
TEST(ImageFile, PngDecodesToTheGreyOpenCvGives) {
  std::vector<std::pair<std::string, std::vector<std::uint8_t>>> cases;
  cv::Mat colour(23, 37, CV_8UC3), alpha(23, 37, CV_8UC4), deep(23, 37, CV_16UC1), deep_colour(23, 37, CV_16UC3);
  cv::randu(colour, 0, 256);
  cv::randu(alpha, 0, 256);
  cv::randu(deep, 0, 65536);
  cv::randu(deep_colour, 0, 65536);
  for (const auto& [name, image] : std::vector<std::pair<std::string, cv::Mat>>{
           {"grey 8-bit", texture({37, 23})}, {"BGR 8-bit", colour}, {"BGRA 8-bit", alpha},
           {"grey 16-bit", deep}, {"BGR 16-bit", deep_colour}}) {
    std::vector<std::uint8_t> png;
    ASSERT_TRUE(cv::imencode(".png", image, png)) << name;
    cases.emplace_back(name, png);
  }
  std::vector<std::uint8_t> bilevel;
  ASSERT_TRUE(cv::imencode(".png", texture({37, 23}) > 128, bilevel, {cv::IMWRITE_PNG_BILEVEL, 1}));
  cases.emplace_back("1-bit grey", bilevel);
  const fs::path data = fs::path(onetip::test::sourceDir()) / "tests/data/png";
  for (const char* file : {"palette_trns.png", "grey2_interlaced.png", "rgb16_interlaced.png", "grey_alpha8.png"}) {
    std::vector<std::uint8_t> bytes;
    ASSERT_FALSE(readFileBytes((data / file).string(), 1 << 20, bytes)) << file;
    cases.emplace_back(file, bytes);
  }
  for (const auto& [name, bytes] : cases) {
    const cv::Mat expected = cv::imdecode(bytes, cv::IMREAD_GRAYSCALE);
    ASSERT_EQ(expected.size(), cv::Size(37, 23)) << name;
    const GreyImage image = decodeGreyImage(bytes.data(), bytes.size(), ImageLimits{});
    ASSERT_FALSE(image.problem) << name << ": " << *image.problem;
    EXPECT_EQ(image.grey.type(), CV_8UC1) << name;
    EXPECT_EQ(cv::norm(image.grey, expected, cv::NORM_INF), 0.0) << name;
  }
}

// A damaged PNG is a reason of ours and nothing on stderr (libpng's default handlers print "libpng error: ...").
TEST(ImageFile, ADamagedPngIsOneReasonAndNothingOnStderr) {
  std::vector<std::uint8_t> png;
  ASSERT_TRUE(cv::imencode(".png", texture({64, 48}), png));
  std::vector<std::uint8_t> truncated(png.begin(), png.begin() + static_cast<long>(png.size() / 2));
  std::vector<std::uint8_t> bad_crc = png;
  const std::string text(bad_crc.begin(), bad_crc.end());
  const size_t idat = text.find("IDAT");
  ASSERT_NE(idat, std::string::npos);
  bad_crc[idat + 20] ^= 0x55;
  // libpng names the damaged chunk: the CRC, or zlib's own check when the changed byte breaks the stream first
  for (const auto& [bytes, reason] : std::vector<std::pair<std::vector<std::uint8_t>, std::string>>{
           {truncated, "cannot decode the PNG: the file ends early (truncated)"},
           {bad_crc, "cannot decode the PNG: IDAT: "}}) {
    ::testing::internal::CaptureStderr();
    const GreyImage image = decodeGreyImage(bytes.data(), bytes.size(), ImageLimits{});
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(err, "");
    ASSERT_TRUE(image.problem);
    EXPECT_EQ(image.problem->rfind(reason, 0), 0u) << *image.problem;
    EXPECT_EQ(image.problem->find('\n'), std::string::npos);
    EXPECT_TRUE(image.grey.empty());
  }
}

// A folder where an image belongs is named as one (opened as a file, it reports 2^63 - 1 bytes).
TEST(ImageFile, AFolderIsNamedAsADirectory) {
  const test_support::ScratchDir dir("onetip-image-file");
  const GreyImage image = readGreyImage(dir.path().string(), ImageLimits{});
  ASSERT_TRUE(image.problem);
  EXPECT_EQ(*image.problem, "is a directory, not a file");
  EXPECT_NE(test_support::inputErrorOf([&] { loadGreyImage(dir.path().string(), {}); }).find(": is a directory"),
            std::string::npos);
}

TEST(ImageFile, HostileHeadersAreReasonsNotExceptions) {
  const ImageLimits limits;
  for (const auto& [file, expected] : std::vector<std::pair<std::string, std::string>>{
           {"png_claims_40000x40000.png", "40000x40000"},
           {"png_claims_32000x32000.png", "32000x32000"},
           {"jpeg_claims_60000x60000.jpg", "60000x60000"},
           {"png_claims_0x0.png", "impossible size"},
           // found by fuzz_frame: libtiff keeps the first ImageLength (20617), a reader keeping the last saw 47
           {"tiff_hides_10000x20617_behind_a_second_length.tif", "size tag given twice"},
           // a 64x64 image in one strip of 10^6 rows: OpenCV would allocate the strip (256 MB)
           {"tiff_strip_of_1000000_rows.tif", "strip or tile of 64000000 pixels"},
           {"truncated_header.png", "unrecognised"},
           {"not_an_image.png", "unrecognised"}}) {
    const GreyImage image = readGreyImage((kCorpus / file).string(), limits);
    ASSERT_TRUE(image.problem) << file;
    EXPECT_NE(image.problem->find(expected), std::string::npos) << file << ": " << *image.problem;
    EXPECT_TRUE(image.grey.empty());
  }
  // a real header over damaged pixel data: decoded or refused, never thrown
  std::vector<std::uint8_t> png;
  ASSERT_TRUE(cv::imencode(".png", texture({64, 64}), png));
  png.resize(png.size() / 2);
  EXPECT_TRUE(decodeGreyImage(png.data(), png.size(), limits).problem);
  EXPECT_NE(test_support::inputErrorOf([] { loadGreyImage((kCorpus / "png_claims_40000x40000.png").string(), {}); })
                .find("png_claims_40000x40000.png"),
            std::string::npos);
}

TEST(ImageFile, FolderSourceCountsAHostileFrameAsSkippedAndGoesOn) {
  const test_support::ScratchDir dir("onetip-image-file");
  const cv::Mat a = texture({160, 120}), b = texture({160, 120});
  ASSERT_TRUE(cv::imwrite(dir.file("000.png"), a));
  fs::copy_file(kCorpus / "png_claims_40000x40000.png", dir.path() / "001.png");
  ASSERT_TRUE(cv::imwrite(dir.file("002.png"), texture({320, 240})));  // wrong size, refused from its header
  ASSERT_TRUE(cv::imwrite(dir.file("003.png"), b));
  FolderSource source(dir.path().string());
  const Frame f0 = source.next(), f1 = source.next(), f2 = source.next(), f3 = source.next();
  ASSERT_TRUE(f0.ok());
  EXPECT_EQ(cv::norm(f0.grey, a, cv::NORM_INF), 0.0);
  EXPECT_EQ(f1.status, FrameStatus::skipped);
  EXPECT_NE(f1.message.find("001.png"), std::string::npos) << f1.message;
  EXPECT_NE(f1.message.find("40000x40000"), std::string::npos) << f1.message;
  EXPECT_EQ(f2.status, FrameStatus::skipped);
  EXPECT_NE(f2.message.find("320x240"), std::string::npos) << f2.message;
  ASSERT_TRUE(f3.ok());
  EXPECT_EQ(cv::norm(f3.grey, b, cv::NORM_INF), 0.0);
  EXPECT_EQ(source.next().status, FrameStatus::end);
  EXPECT_EQ(source.counters().delivered, 2);
  EXPECT_EQ(source.counters().skipped, 2);
}

}  // namespace
