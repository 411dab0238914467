// View split: halves as ROIs (no copy), flips, the point mapping, bad frames.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "vision/view_split.hpp"

namespace onetip::vision {
namespace {

TEST(ViewSplit, HalvesAreRoisWithFlips) {
  StereoCalibration calib;
  calib.image_width = 100, calib.image_height = 40, calib.split_x = 60, calib.flip_right = true;
  cv::Mat frame(40, 100, CV_8UC1);
  for (int x = 0; x < 100; ++x) frame.col(x).setTo(x);
  const StereoViews v = splitViews(frame, calib);
  EXPECT_EQ(v.left.width(), 60);
  EXPECT_EQ(v.right.width(), 40);
  EXPECT_EQ(v.right.height(), 40);
  EXPECT_EQ(v.left.raw.data, frame.data);  // no copy
  EXPECT_EQ(v.right.raw.data, frame.data + 60);
  EXPECT_FALSE(v.left.flipped);
  EXPECT_TRUE(v.right.flipped);
  // View x of the flipped right half: raw column w - 1 - x, i.e. frame column 60 + 39 - x.
  const cv::Point2f raw = v.right.toRaw({5.25f, 7.0f});
  EXPECT_FLOAT_EQ(raw.x, 33.75f);
  EXPECT_FLOAT_EQ(raw.y, 7.0f);
  EXPECT_EQ(v.right.raw.at<unsigned char>(7, 34), 60 + 39 - 5);
  EXPECT_FLOAT_EQ(v.right.toView(raw).x, 5.25f);  // its own inverse
  EXPECT_FLOAT_EQ(v.left.toView({5.25f, 7.0f}).x, 5.25f);
  std::vector<cv::Point2f> pts{{0, 0}, {39, 1}};
  v.right.toViewInPlace(pts);
  EXPECT_FLOAT_EQ(pts[0].x, 39.0f);
  EXPECT_FLOAT_EQ(pts[1].x, 0.0f);
}

TEST(ViewSplit, BadFramesThrow) {
  StereoCalibration calib;
  calib.image_width = 100, calib.image_height = 40, calib.split_x = 60;
  EXPECT_THROW(splitViews(cv::Mat(), calib), InputError);
  EXPECT_THROW(splitViews(cv::Mat(40, 100, CV_8UC3), calib), InputError);
  EXPECT_THROW(splitViews(cv::Mat(41, 100, CV_8UC1), calib), InputError);
  calib.split_x = 100;
  EXPECT_THROW(splitViews(cv::Mat(40, 100, CV_8UC1), calib), InputError);
}

}  // namespace
}  // namespace onetip::vision
