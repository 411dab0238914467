// Corner detector against exact synthetic ground truth (synthetic_board.hpp):
// detection rate and 2-D RMS error under deformation (local scale 0.6-1.6x,
// shear, rotation), blur, noise sigma 2 and uneven lighting; bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "synthetic_board.hpp"
#include "vision/corner_detector.hpp"

namespace onetip::vision {
namespace {

using testing::BoardLook;
using testing::BoardWarp;

struct Accuracy {
  int visible = 0, found = 0;
  double rms = 0;
};

// Each visible ground-truth corner matched to the nearest detection within 2 px.
Accuracy measure(const std::vector<Corner>& corners, const std::vector<testing::GroundTruthCorner>& truth) {
  Accuracy a;
  double sum = 0;
  for (const auto& t : truth) {
    if (!t.visible) continue;
    ++a.visible;
    double best = 4.0;
    for (const Corner& c : corners) {
      const cv::Point2d d = cv::Point2d(c.pt) - t.pixel;
      best = std::min(best, d.dot(d));
    }
    if (best < 4.0) ++a.found, sum += best;
  }
  a.rms = a.found ? std::sqrt(sum / a.found) : 0;
  return a;
}

struct Case {
  const char* name;
  BoardWarp warp;
};

std::vector<Case> deformations() {
  std::vector<Case> cases;
  BoardWarp w;
  cases.push_back({"rest", w});
  w.bulge = 0.667;  // 0.6x at the centre
  cases.push_back({"compressed 0.6x", w});
  w.bulge = -0.375;  // 1.6x at the centre
  cases.push_back({"stretched 1.6x", w});
  w.bulge = 0.5, w.rotation_deg = 25, w.shear = 0.25;
  cases.push_back({"bulge + rotation + shear", w});
  return cases;
}

Accuracy detectCase(const BoardWarp& warp, const BoardLook& look, const CornerDetectorOptions& options = {}) {
  const cv::Size size(960, 1080);
  const cv::Mat img = testing::renderBoard(warp, look, size);
  return measure(CornerDetector(options).detect(img), testing::groundTruthCorners(warp, look, size));
}

TEST(CornerDetector, NoiseFreeAccuracyUnderDeformation) {
  BoardLook look;
  look.blur_sigma = 0.7;  // optics
  for (const Case& c : deformations()) {
    const Accuracy a = detectCase(c.warp, look);
    std::printf("noise-free %-26s found %d/%d rms %.4f px\n", c.name, a.found, a.visible, a.rms);
    EXPECT_GE(a.found, 0.995 * a.visible) << c.name;
    EXPECT_LE(a.rms, 0.05) << c.name;
  }
}

TEST(CornerDetector, NoisyBlurredUnevenlyLitAccuracy) {
  BoardLook look;
  look.blur_sigma = 1.2, look.noise_sigma = 2.0, look.light_ramp = 0.6;
  for (const Case& c : deformations()) {
    look.seed += 1;
    const Accuracy a = detectCase(c.warp, look);
    std::printf("sigma 2    %-26s found %d/%d rms %.4f px\n", c.name, a.found, a.visible, a.rms);
    EXPECT_GE(a.found, 0.995 * a.visible) << c.name;
    EXPECT_LE(a.rms, 0.10) << c.name;
  }
}

TEST(CornerDetector, SubpixelMethodsCompared) {
  // The default (saddle fit) must be at least as accurate as gradient
  // orthogonality (cv::cornerSubPix's principle) on noisy, deformed views.
  BoardLook look;
  look.blur_sigma = 1.0, look.noise_sigma = 2.0;
  const cv::Size size(960, 1080);
  double sum[2] = {0, 0};
  int n[2] = {0, 0};
  for (const Case& c : deformations()) {
    const cv::Mat img = testing::renderBoard(c.warp, look, size);
    const auto truth = testing::groundTruthCorners(c.warp, look, size);
    for (int m = 0; m < 2; ++m) {
      CornerDetectorOptions o;
      o.subpixel.method = m == 0 ? SubpixelMethod::SaddleFit : SubpixelMethod::GradientOrthogonality;
      const Accuracy a = measure(CornerDetector(o).detect(img), truth);
      sum[m] += a.rms * a.rms * a.found, n[m] += a.found;
    }
  }
  const double rms[2] = {std::sqrt(sum[0] / n[0]), std::sqrt(sum[1] / n[1])};
  std::printf("sub-pixel RMS at sigma 2: saddle fit %.4f px, gradient orthogonality %.4f px\n", rms[0], rms[1]);
  EXPECT_EQ(CornerDetectorOptions{}.subpixel.method, SubpixelMethod::SaddleFit);
  EXPECT_LE(rms[0], rms[1]);
}

TEST(CornerDetector, BadInput) {
  const CornerDetector detector;
  EXPECT_THROW(detector.detect(cv::Mat()), InputError);
  EXPECT_THROW(detector.detect(cv::Mat(100, 100, CV_8UC3, cv::Scalar::all(0))), InputError);
  EXPECT_THROW(detector.detect(cv::Mat(100, 100, CV_32F, cv::Scalar::all(0))), InputError);
  EXPECT_TRUE(detector.detect(cv::Mat(5, 5, CV_8UC1, cv::Scalar::all(0))).empty());
  EXPECT_TRUE(detector.detect(cv::Mat(480, 640, CV_8UC1, cv::Scalar::all(128))).empty());  // blank
  EXPECT_FALSE(detector.detectNear(cv::Mat(20, 20, CV_8UC1, cv::Scalar::all(0)), {2, 2}, 10).has_value());
  CornerDetectorOptions bad;
  bad.samples_per_ring = 10;
  EXPECT_THROW(CornerDetector{bad}, InputError);
  bad = {};
  bad.outer_radius_px = 2;
  EXPECT_THROW(CornerDetector{bad}, InputError);
  bad = {};
  bad.prefilter_downsample = 3;
  EXPECT_THROW(CornerDetector{bad}, InputError);
}

}  // namespace
}  // namespace onetip::vision
