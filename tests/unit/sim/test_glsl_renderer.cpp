// The GLSL renderer (headless EGL): same corner-accuracy acceptance as the
// CPU renderer, agreement with it pixel by pixel, and its flip and effects
// plumbing. Skipped where no headless EGL / OpenGL 3.3 core context can be made.
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>

#include "render_accuracy.hpp"
#include "sim/glsl_renderer.hpp"

namespace onetip::sim {
namespace {

using testsupport::AccuracyCase;
using testsupport::accuracyCases;
using testsupport::deformedPoint;
using testsupport::expectCornersMatchTruth;
using testsupport::noEffects;
using testsupport::padSheet;

// One renderer for the whole suite (context creation costs ~50 ms).
const GlslFrameRenderer* sharedRenderer(std::string& why_not) {
  static std::string failure;
  static const std::unique_ptr<GlslFrameRenderer> renderer = []() -> std::unique_ptr<GlslFrameRenderer> {
    try {
      return std::make_unique<GlslFrameRenderer>(CameraRig::fromOptions({}));
    } catch (const std::runtime_error& e) {
      failure = e.what();
      return nullptr;
    }
  }();
  why_not = failure;
  return renderer.get();
}

#define REQUIRE_GLSL_RENDERER(name)                      \
  std::string why_not;                                   \
  const GlslFrameRenderer* name = sharedRenderer(why_not); \
  if (!(name)) GTEST_SKIP() << why_not

class GlslRendererAccuracy : public ::testing::TestWithParam<AccuracyCase> {};

TEST_P(GlslRendererAccuracy, ProjectedTrueCornersMatchRenderedCorners) {
  REQUIRE_GLSL_RENDERER(renderer);
  const AccuracyCase& c = GetParam();
  const CheckerSheet sheet = padSheet(c.shape, c.spacing_mm);
  ImageEffects effects = noEffects();
  effects.noise_sigma = c.noise_sigma;
  effects.blur_sigma = c.blur_sigma;
  expectCornersMatchTruth(renderer->render({sheet}, effects, 7), renderer->rig(), sheet.texture, c.shape,
                          std::string("glsl ") + c.name);
}

INSTANTIATE_TEST_SUITE_P(Sheets, GlslRendererAccuracy, ::testing::ValuesIn(accuracyCases()),
                         [](const auto& test_info) { return std::string(test_info.param.name); });

TEST(GlslRenderer, AgreesWithTheCpuRenderer) {
  REQUIRE_GLSL_RENDERER(glsl);
  std::printf("GL renderer: %s\n", glsl->glRenderer().c_str());
  const FrameRenderer cpu(glsl->rig());
  const std::vector<CheckerSheet> sheets{padSheet(deformedPoint)};
  ImageEffects effects;  // noise, occlusion and dust too: the same seeded effects follow
  effects.occlusion_fraction = 0.2;
  effects.dust_blobs = 3;
  const cv::Mat a = glsl->render(sheets, effects, 5), b = cpu.render(sheets, effects, 5);
  cv::Mat diff;
  cv::absdiff(a, b, diff);
  const double mean = cv::mean(diff)[0];
  const double share_off_by_more_than_2 = cv::countNonZero(diff > 2) / double(diff.total());
  std::printf("GLSL vs CPU: mean |diff| %.3f grey levels, %.4f %% of pixels differ by > 2\n", mean,
              100 * share_off_by_more_than_2);
  EXPECT_LT(mean, 0.2);
  EXPECT_LT(share_off_by_more_than_2, 0.002);  // only where the two rasterisers snap an edge differently
}

}  // namespace
}  // namespace onetip::sim
