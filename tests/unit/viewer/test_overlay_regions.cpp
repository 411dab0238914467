// viewer/overlay_regions: the rectangles cover every pixel with alpha > 0 and
// nothing twice, checked pixel by pixel against the overlay itself.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <random>

#include "viewer/overlay_regions.hpp"

namespace onetip::viewer {
namespace {

// Pixels covered by each rectangle, counted per pixel.
cv::Mat coverage(cv::Size size, const std::vector<cv::Rect>& regions) {
  cv::Mat count(size, CV_32S, cv::Scalar(0));
  for (const cv::Rect& r : regions) count(r) += 1;
  return count;
}

void expectExactCover(const cv::Mat& bgra, int tile) {
  const std::vector<cv::Rect> regions = overlayRegions(bgra, tile);
  const cv::Rect whole({0, 0}, bgra.size());
  for (const cv::Rect& r : regions) ASSERT_EQ(r & whole, r) << "outside the image: " << r;
  const cv::Mat count = coverage(bgra.size(), regions);
  int uncovered = 0, twice = 0;
  for (int y = 0; y < bgra.rows; ++y)
    for (int x = 0; x < bgra.cols; ++x) {
      if (bgra.at<cv::Vec4b>(y, x)[3] != 0 && count.at<int>(y, x) == 0) ++uncovered;
      if (count.at<int>(y, x) > 1) ++twice;
    }
  EXPECT_EQ(uncovered, 0);
  EXPECT_EQ(twice, 0);
  // Every tile a rectangle covers holds content: nothing is blended for nothing.
  for (const cv::Rect& r : regions)
    for (int y = r.y; y < r.br().y; y += tile)
      for (int x = r.x; x < r.br().x; x += tile) {
        const cv::Rect t = cv::Rect(x, y, tile, tile) & r;
        std::vector<cv::Mat> channels;
        cv::split(bgra(t), channels);
        EXPECT_GT(cv::countNonZero(channels[3]), 0) << "an empty tile at " << t;
      }
}

TEST(OverlayRegions, CoverTextAndBarsExactlyAndLittleElse) {
  cv::Mat hud(363, 650, CV_8UC4, cv::Scalar::all(0));  // sizes not a multiple of the tile
  cv::rectangle(hud, {0, 0, 650, 22}, cv::Scalar(20, 20, 20, 190), cv::FILLED);
  cv::putText(hud, "camera  frame 12", {6, 16}, cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(235, 235, 235, 255));
  cv::rectangle(hud, {400, 200, 250, 163}, cv::Scalar(55, 55, 55, 255), cv::FILLED);
  cv::putText(hud, "|u|: 0 .. 2.0 mm", {8, 340}, cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(160, 160, 160, 255));
  hud.at<cv::Vec4b>(362, 649) = {1, 1, 1, 1};  // the last pixel, in a clipped tile
  for (int tile : {1, 7, 16, 64}) {
    SCOPED_TRACE("tile " + std::to_string(tile));
    expectExactCover(hud, tile);
  }
  double area = 0;
  for (const cv::Rect& r : overlayRegions(hud, 16)) area += r.area();
  EXPECT_LT(area, 0.35 * static_cast<double>(hud.total()));
}

TEST(OverlayRegions, RandomSpecklesEmptyAndFull) {
  std::mt19937 rng(7);
  cv::Mat speckles(100, 130, CV_8UC4, cv::Scalar::all(0));
  std::uniform_int_distribution<int> x(0, 129), y(0, 99);
  for (int i = 0; i < 40; ++i) speckles.at<cv::Vec4b>(y(rng), x(rng)) = {0, 0, 0, 3};  // alpha only
  expectExactCover(speckles, 8);

  const cv::Mat empty(100, 130, CV_8UC4, cv::Scalar(255, 255, 255, 0));  // colour without alpha is nothing
  EXPECT_TRUE(overlayRegions(empty, 8).empty());
  const cv::Mat full(100, 130, CV_8UC4, cv::Scalar::all(9));
  const std::vector<cv::Rect> all = overlayRegions(full, 8);
  ASSERT_EQ(all.size(), 1U);
  EXPECT_EQ(all.front(), cv::Rect(0, 0, 130, 100));
}

TEST(OverlayRegions, RejectsWhatIsNotAnOverlay) {
  EXPECT_THROW(overlayRegions(cv::Mat(), 8), std::invalid_argument);
  EXPECT_THROW(overlayRegions(cv::Mat(10, 10, CV_8UC3, cv::Scalar::all(1)), 8), std::invalid_argument);
  EXPECT_THROW(overlayRegions(cv::Mat(10, 10, CV_8UC4, cv::Scalar::all(1)), 0), std::invalid_argument);
}

}  // namespace
}  // namespace onetip::viewer
