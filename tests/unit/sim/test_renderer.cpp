// Renderer tests: corner accuracy against projected ground truth, flips,
// image effects, determinism and option validation.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "render_accuracy.hpp"
#include "sim/renderer.hpp"

namespace onetip::sim {
namespace {

using testsupport::deformedPoint;
using testsupport::noEffects;
using testsupport::padSheet;
using testsupport::patternToPlane;
using testsupport::restPoint;
using testsupport::SheetShape;
using testsupport::AccuracyCase;
using testsupport::accuracyCases;
using testsupport::cornerErrors;
using testsupport::expectCornersMatchTruth;

class RendererAccuracy : public ::testing::TestWithParam<AccuracyCase> {};

TEST_P(RendererAccuracy, ProjectedTrueCornersMatchRenderedCorners) {
  const AccuracyCase& c = GetParam();
  const FrameRenderer renderer(CameraRig::fromOptions({}));
  const CheckerSheet sheet = padSheet(c.shape, c.spacing_mm);
  ImageEffects effects = noEffects();
  effects.noise_sigma = c.noise_sigma;
  effects.blur_sigma = c.blur_sigma;
  expectCornersMatchTruth(renderer.render({sheet}, effects, 7), renderer.rig(), sheet.texture, c.shape,
                          std::string("cpu ") + c.name);
}

INSTANTIATE_TEST_SUITE_P(Sheets, RendererAccuracy, ::testing::ValuesIn(accuracyCases()),
                         [](const auto& test_info) { return std::string(test_info.param.name); });

// Independent reference: a point-sampled ray cast of the flat sheet
// (z = 0 in S), supersampled 8 x 8 per pixel, through the exact inverse of
// the camera model (cv::undistortPoints). Patches straddle inner corners, the
// board's edge and the border's edge.
double referenceTexture(const CheckerTexture& t, double u, double v) {
  const double lo = -t.square_mm, hi_u = t.cols * t.square_mm, hi_v = t.rows * t.square_mm;
  if (u < lo - t.border_mm || u > hi_u + t.border_mm || v < lo - t.border_mm || v > hi_v + t.border_mm)
    return t.background;
  if (u < lo || u > hi_u || v < lo || v > hi_v) return t.light;
  const auto i = static_cast<long>(std::floor(u / t.square_mm)), j = static_cast<long>(std::floor(v / t.square_mm));
  return (i + j) % 2 == 0 ? t.dark : t.light;
}

cv::Mat1f rayCastPatch(const VirtualCamera& cam, const CheckerTexture& t, cv::Rect patch) {
  constexpr int kSub = 8;
  std::vector<cv::Point2f> samples, rays;
  for (int y = patch.y; y < patch.y + patch.height; ++y)
    for (int x = patch.x; x < patch.x + patch.width; ++x)
      for (int k = 0; k < kSub * kSub; ++k)
        samples.emplace_back(x - 0.5F + (k % kSub + 0.5F) / kSub, y - 0.5F + (k / kSub + 0.5F) / kSub);
  cv::undistortPoints(samples, rays, cam.K, cam.D, cv::noArray(), cv::noArray(),
                      cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 50, 1e-12));
  const Eigen::Isometry3d sensor_from_camera = cam.camera_from_sensor.inverse();
  const Eigen::Vector2d origin = patternToPlane(t, 0, 0);
  cv::Mat1f out(patch.size(), 0.0F);
  for (size_t i = 0; i < rays.size(); ++i) {
    const Eigen::Vector3d dir = sensor_from_camera.linear() * Eigen::Vector3d(rays[i].x, rays[i].y, 1.0);
    const Eigen::Vector3d c = sensor_from_camera.translation();
    const Eigen::Vector3d hit = c - c.z() / dir.z() * dir;
    const int pixel = static_cast<int>(i) / (kSub * kSub);
    out(pixel / patch.width, pixel % patch.width) +=
        static_cast<float>(referenceTexture(t, hit.x() - origin.x(), hit.y() - origin.y()) / (kSub * kSub));
  }
  return out;
}

TEST(Renderer, MatchesASupersampledRayCast) {
  CameraRigOptions options;
  options.flip_left = false;
  const CameraRig rig = CameraRig::fromOptions(options);
  const CheckerSheet sheet = padSheet(restPoint);
  const cv::Mat frame = FrameRenderer(rig).render({sheet}, noEffects(), 0);
  const CheckerTexture& t = sheet.texture;
  // (u, v) patch centres: corners near the middle and the edges, the board's edge, the border's edge.
  const std::vector<cv::Point2d> centres{{0, 0}, {8 * 1.2, 8 * 1.2}, {16 * 1.2, 3 * 1.2}, {-1.2, 6.0}, {-2.4, 9.0}};
  for (const cv::Point2d& uv : centres) {
    const Eigen::Vector2d p = patternToPlane(t, uv.x, uv.y);
    Eigen::Vector2d px;
    ASSERT_TRUE(rig.left.project(rig.left.camera_from_sensor * restPoint(p.x(), p.y()), px));
    const cv::Rect patch(static_cast<int>(px.x()) - 12, static_cast<int>(px.y()) - 12, 25, 25);
    cv::Mat1f rendered;
    frame(patch).convertTo(rendered, CV_32F);
    const cv::Mat1f reference = rayCastPatch(rig.left, t, patch);
    const double rms = cv::norm(rendered, reference, cv::NORM_L2) / std::sqrt(double(patch.area()));
    const double max = cv::norm(rendered, reference, cv::NORM_INF);
    std::printf("patch at (u, v) = (%.1f, %.1f): rms %.2f, max %.1f grey levels\n", uv.x, uv.y, rms, max);
    EXPECT_LT(rms, 2.0);   // edges span 170 grey levels; the filters differ in detail only
    EXPECT_LT(max, 16.0);
  }
}

// The accuracy check must be able to fail: a renderer whose principal point
// is 0.5 px off from the calibration is caught.
TEST(Renderer, AccuracyCheckDetectsHalfPixelCalibrationError) {
  const CameraRig truth = CameraRig::fromOptions({});
  CameraRig shifted = truth;
  shifted.left.K(0, 2) += 0.5;
  const CheckerSheet sheet = padSheet(restPoint);
  const cv::Mat frame = FrameRenderer(shifted).render({sheet}, noEffects(), 1);
  EXPECT_GT(cornerErrors(frame, truth, sheet.texture, restPoint, 0).rms, 0.4);
  EXPECT_LT(cornerErrors(frame, truth, sheet.texture, restPoint, 1).rms, 0.1);
}

TEST(Renderer, FlipMirrorsEachHalf) {
  CameraRigOptions plain;
  plain.flip_left = plain.flip_right = false;
  CameraRigOptions mirrored;
  mirrored.flip_right = false;  // left flipped only
  const CheckerSheet sheet = padSheet(deformedPoint);
  ImageEffects effects;  // noise on: its pattern must be mirrored too
  effects.dust_blobs = 3;
  const cv::Mat a = FrameRenderer(CameraRig::fromOptions(plain)).render({sheet}, effects, 3);
  const cv::Mat b = FrameRenderer(CameraRig::fromOptions(mirrored)).render({sheet}, effects, 3);
  const cv::Rect left(0, 0, 960, 1080), right(960, 0, 960, 1080);
  cv::Mat flipped;
  cv::flip(a(left), flipped, 1);
  EXPECT_EQ(cv::norm(flipped, b(left), cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(a(right), b(right), cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a(left), b(left), cv::NORM_INF), 100.0);  // the flip did something
}

// Watertight rasterisation: inside the sheet's silhouette no pixel is left
// at the housing grey (holes along shared triangle edges would be).
TEST(Renderer, NoHolesInsideTheSheet) {
  const cv::Mat frame = FrameRenderer(CameraRig::fromOptions({})).render({padSheet(deformedPoint)}, noEffects(), 0);
  cv::Mat housing = (frame == 20) / 255;  // 1 where housing grey
  ASSERT_GT(cv::countNonZero(housing), 0) << "the sheet should not fill the whole frame";
  // Flood the housing that touches the frame's outside; whatever remains is a hole.
  cv::Mat padded;
  cv::copyMakeBorder(housing, padded, 1, 1, 1, 1, cv::BORDER_CONSTANT, 1);
  cv::floodFill(padded, cv::Point(0, 0), 0);
  EXPECT_EQ(cv::countNonZero(padded), 0);
}

// The depth test, not the drawing order, decides which sheet is seen.
TEST(Renderer, NearerSheetHidesFartherOneInAnyOrder) {
  const FrameRenderer renderer(CameraRig::fromOptions({}));
  const CheckerSheet far_sheet = padSheet(restPoint, 0.3);
  CheckerSheet near_sheet = padSheet([](double x, double y) { return Eigen::Vector3d(x, y, -2.0); }, 0.3, 4.0);
  near_sheet.texture.dark = near_sheet.texture.light = near_sheet.texture.background = 250;
  const cv::Mat a = renderer.render({far_sheet, near_sheet}, noEffects(), 0);
  const cv::Mat b = renderer.render({near_sheet, far_sheet}, noEffects(), 0);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
  // The near sheet spans about +-4 mm around the S origin, ~150 px wide: its centre is uniform 250.
  Eigen::Vector2d centre;
  ASSERT_TRUE(renderer.rig().right.project(renderer.rig().right.camera_from_sensor * Eigen::Vector3d(0, 0, -2), centre));
  const cv::Rect middle(960 + 959 - static_cast<int>(centre.x()) - 20, static_cast<int>(centre.y()) - 20, 40, 40);
  double lo = 0, hi = 0;
  cv::minMaxLoc(a(middle), &lo, &hi);
  EXPECT_EQ(lo, 250);
  EXPECT_EQ(hi, 250);
}

TEST(Renderer, EmptySceneIsDarkHousing) {
  const cv::Mat frame = FrameRenderer(CameraRig::fromOptions({})).render({}, noEffects(), 0);
  double lo = 0, hi = 0;
  cv::minMaxLoc(frame, &lo, &hi);
  EXPECT_EQ(lo, 20);
  EXPECT_EQ(hi, 20);
}

// Renders the deformed pad with and without one effect (no noise unless asked).
struct EffectPair {
  cv::Mat clean, changed;
};
EffectPair renderWith(const ImageEffects& effects, std::uint64_t seed = 11) {
  const FrameRenderer renderer(CameraRig::fromOptions({}));
  const std::vector<CheckerSheet> sheets{padSheet(deformedPoint)};
  return {renderer.render(sheets, noEffects(), seed), renderer.render(sheets, effects, seed)};
}

TEST(RendererEffects, ExposureScalesGreyLevels) {
  ImageEffects e = noEffects();
  e.exposure = 0.6;
  const EffectPair p = renderWith(e);
  cv::Mat expected;
  p.clean.convertTo(expected, CV_8U, 0.6);
  EXPECT_LE(cv::norm(expected, p.changed, cv::NORM_INF), 1.0);
  EXPECT_NEAR(cv::mean(p.changed)[0] / cv::mean(p.clean)[0], 0.6, 0.01);
}

TEST(RendererEffects, OcclusionCoversTheStatedFractionOfThePad) {
  for (const double fraction : {0.2, 0.5}) {
    ImageEffects e = noEffects();
    e.occlusion_fraction = fraction;
    const EffectPair p = renderWith(e);
    cv::Mat pad, hidden, changed;
    cv::compare(p.clean, 30, pad, cv::CMP_GT);  // housing is 20, the sheet at least 40
    cv::compare(p.changed, 10, hidden, cv::CMP_LE);
    cv::compare(p.clean, p.changed, changed, cv::CMP_NE);
    for (const cv::Rect half : {cv::Rect(0, 0, 960, 1080), cv::Rect(960, 0, 960, 1080)}) {
      const double pad_pixels = cv::countNonZero(pad(half));
      EXPECT_NEAR(cv::countNonZero(pad(half) & hidden(half)) / pad_pixels, fraction, 0.01);
      EXPECT_EQ(cv::countNonZero(changed(half) & ~hidden(half)), 0) << "only the band may change";
    }
  }
}

TEST(RendererEffects, DustDarkensAndSpecularSaturates) {
  ImageEffects dust = noEffects();
  dust.dust_blobs = 10;
  const EffectPair d = renderWith(dust);
  EXPECT_GT(cv::countNonZero(d.changed < d.clean), 500);
  EXPECT_EQ(cv::countNonZero(d.changed > d.clean), 0);

  ImageEffects spots = noEffects();
  spots.specular_spots = 10;
  const EffectPair s = renderWith(spots);
  EXPECT_GT(cv::countNonZero(s.changed == 255), 20);
  EXPECT_EQ(cv::countNonZero(s.changed < s.clean), 0);
}

TEST(RendererEffects, VignettingDarkensCornersNotCentre) {
  ImageEffects e = noEffects();
  e.vignetting = 0.5;
  const EffectPair p = renderWith(e);
  const auto ratio = [&](cv::Rect r) { return cv::mean(p.changed(r))[0] / cv::mean(p.clean(r))[0]; };
  EXPECT_NEAR(ratio({470, 530, 20, 20}), 1.0, 0.01);            // left view centre
  EXPECT_NEAR(ratio({0, 0, 6, 6}), 0.5, 0.06);                   // its corners lose ~50 %
  EXPECT_NEAR(ratio({1914, 1074, 6, 6}), 0.5, 0.06);
}

TEST(RendererEffects, LightGradientIsALinearRampOfTheStatedStrength) {
  ImageEffects e = noEffects();
  e.light_gradient = 0.4;
  const EffectPair p = renderWith(e);
  // Fit gain = a + b x + c y over bright pixels of the left view; expect a
  // good fit whose range across the view is the stated strength.
  std::vector<cv::Vec3d> rows;
  std::vector<double> gains;
  for (int y = 0; y < 1080; y += 7)
    for (int x = 0; x < 960; x += 7)
      if (p.clean.at<uchar>(y, x) > 150) {
        rows.push_back({1.0, double(x), double(y)});
        gains.push_back(double(p.changed.at<uchar>(y, x)) / p.clean.at<uchar>(y, x));
      }
  cv::Mat A(static_cast<int>(rows.size()), 3, CV_64F, rows.data()), b(gains, false), coef;
  cv::solve(A, b, coef, cv::DECOMP_SVD);
  const cv::Mat residual = A * coef - b;
  EXPECT_LT(cv::norm(residual) / std::sqrt(double(rows.size())), 0.01);
  const double gx = coef.at<double>(1), gy = coef.at<double>(2);
  const double span = std::abs(gx) * 960 + std::abs(gy) * 1080;  // gain change across the view
  EXPECT_NEAR(span, 0.4, 0.03);
}

TEST(RendererEffects, BlurSmoothsAndNoiseHasTheStatedSigma) {
  ImageEffects blur = noEffects();
  blur.blur_sigma = 2.0;
  const EffectPair b = renderWith(blur);
  cv::Mat lap_clean, lap_blur;
  cv::Laplacian(b.clean, lap_clean, CV_32F);
  cv::Laplacian(b.changed, lap_blur, CV_32F);
  EXPECT_LT(cv::norm(lap_blur), 0.5 * cv::norm(lap_clean));
  EXPECT_NEAR(cv::mean(b.changed)[0], cv::mean(b.clean)[0], 0.5);

  ImageEffects noise = noEffects();
  noise.noise_sigma = 3.0;
  const EffectPair n = renderWith(noise);
  cv::Mat diff;
  cv::subtract(n.changed, n.clean, diff, cv::noArray(), CV_32F);
  cv::Scalar mean, stddev;
  cv::meanStdDev(diff, mean, stddev, (n.clean > 30) & (n.clean < 220));  // away from saturation
  EXPECT_NEAR(mean[0], 0.0, 0.05);
  EXPECT_NEAR(stddev[0], std::sqrt(9.0 + 1.0 / 12), 0.1);  // plus 8-bit rounding
}

TEST(RendererEffects, DeterministicFromTheSeed) {
  ImageEffects e;
  e.noise_sigma = 2;
  e.dust_blobs = 4;
  e.specular_spots = 4;
  e.occlusion_fraction = 0.2;
  e.light_gradient = 0.3;
  const FrameRenderer renderer(CameraRig::fromOptions({}));
  const std::vector<CheckerSheet> sheets{padSheet(restPoint, 0.3)};
  const cv::Mat a = renderer.render(sheets, e, 42), b = renderer.render(sheets, e, 42),
                c = renderer.render(sheets, e, 43);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a, c, cv::NORM_L1), 1e5);
}

TEST(RendererEffects, ValidateNamesTheBadField) {
  const auto expectError = [](auto mutate, const std::string& field) {
    ImageEffects e;
    mutate(e);
    try {
      e.validate();
      ADD_FAILURE() << field << " accepted";
    } catch (const InputError& err) {
      EXPECT_NE(std::string(err.what()).find(field), std::string::npos) << err.what();
    }
  };
  expectError([](ImageEffects& e) { e.noise_sigma = -1; }, "noise_sigma");
  expectError([](ImageEffects& e) { e.blur_sigma = NAN; }, "blur_sigma");
  expectError([](ImageEffects& e) { e.vignetting = 1.5; }, "vignetting");
  expectError([](ImageEffects& e) { e.exposure = 0.1; }, "exposure");
  expectError([](ImageEffects& e) { e.light_gradient = -0.1; }, "light_gradient");
  expectError([](ImageEffects& e) { e.dust_blobs = -1; }, "dust_blobs");
  expectError([](ImageEffects& e) { e.specular_spots = 1000; }, "specular_spots");
  expectError([](ImageEffects& e) { e.occlusion_fraction = 0.95; }, "occlusion_fraction");
  EXPECT_NO_THROW(ImageEffects{}.validate());

  const FrameRenderer renderer(CameraRig::fromOptions({}));
  ImageEffects bad;
  bad.exposure = 5;
  EXPECT_THROW(renderer.render({}, bad, 0), InputError);
  CheckerSheet broken = padSheet(restPoint, 0.5);
  broken.position.pop_back();
  EXPECT_THROW(renderer.render({broken}, ImageEffects{}, 0), InputError);
}

}  // namespace
}  // namespace onetip::sim
