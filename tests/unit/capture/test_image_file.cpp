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
