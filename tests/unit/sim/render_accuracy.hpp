// tests/unit/sim/render_accuracy.hpp — the renderers' corner-accuracy
// acceptance check: the true 3-D inner corners of a sheet, projected with
// the exact calibration (VirtualCamera::project, mirrored if the view is
// flipped), against the corners cv::cornerSubPix finds on the rendered frame.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "render_test_sheets.hpp"
#include "sim/camera_rig.hpp"

namespace onetip::sim::testsupport {

struct CornerErrors {
  double rms = 0, max = 0;
  int count = 0;
};

// Projects every inner corner's true 3-D point through the view's camera
// (mirrored into the raw half if flipped), refines it on the frame with
// cv::cornerSubPix started 0.6 px away, and compares.
inline CornerErrors cornerErrors(const cv::Mat& frame, const CameraRig& rig, const CheckerTexture& texture,
                          const SheetShape& shape, int view) {
  const VirtualCamera& cam = view == 0 ? rig.left : rig.right;
  constexpr double kMargin = 12;  // keep the search window inside the half
  std::vector<cv::Point2f> truth, found;
  for (int row = 0; row < texture.rows; ++row)
    for (int col = 0; col < texture.cols; ++col) {
      const Eigen::Vector2d p = patternToPlane(texture, col * texture.square_mm, row * texture.square_mm);
      Eigen::Vector2d px;
      if (!cam.project(cam.camera_from_sensor * shape(p.x(), p.y()), px)) continue;
      if (cam.flip) px.x() = rig.view_width - 1 - px.x();
      if (px.x() < kMargin || px.y() < kMargin || px.x() > rig.view_width - 1 - kMargin ||
          px.y() > rig.view_height - 1 - kMargin)
        continue;
      const cv::Point2f t(static_cast<float>(px.x() + view * rig.view_width), static_cast<float>(px.y()));
      truth.push_back(t);
      found.push_back(t + cv::Point2f((row + col) % 2 ? 0.6F : -0.6F, row % 2 ? -0.6F : 0.6F));
    }
  cv::cornerSubPix(frame, found, cv::Size(6, 6), cv::Size(-1, -1),
                   cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 100, 1e-4));
  CornerErrors e;
  for (size_t i = 0; i < truth.size(); ++i) {
    const double d = cv::norm(found[i] - truth[i]);
    e.rms += d * d;
    e.max = std::max(e.max, d);
  }
  e.count = static_cast<int>(truth.size());
  e.rms = std::sqrt(e.rms / std::max(1, e.count));
  return e;
}

// The acceptance check on one rendered frame: in both views the projected
// true corners lie within 0.1 px RMS (0.3 px max) of the rendered ones, and
// most of the 289 corners are checked.
inline void expectCornersMatchTruth(const cv::Mat& frame, const CameraRig& rig, const CheckerTexture& texture,
                                    const SheetShape& shape, const std::string& label) {
  ASSERT_EQ(frame.type(), CV_8UC1);
  ASSERT_EQ(frame.size(), cv::Size(2 * rig.view_width, rig.view_height));
  for (int view = 0; view < 2; ++view) {
    const CornerErrors e = cornerErrors(frame, rig, texture, shape, view);
    std::printf("%s view %d: %d corners, rms %.4f px, max %.4f px\n", label.c_str(), view, e.count, e.rms, e.max);
    EXPECT_GE(e.count, 250) << label << " view " << view;
    EXPECT_LT(e.rms, 0.1) << label << " view " << view;
    EXPECT_LT(e.max, 0.3) << label << " view " << view;
  }
}

struct AccuracyCase {
  const char* name;
  SheetShape shape;
  double spacing_mm;
  double noise_sigma;
  double blur_sigma = 0.0;
};

inline std::vector<AccuracyCase> accuracyCases() {
  return {{"rest", restPoint, 0.15, 0.0},
          {"rest_noisy", restPoint, 0.15, 2.0},
          {"deformed", deformedPoint, 0.15, 0.0},
          {"deformed_noisy", deformedPoint, 0.15, 2.0},
          // corners between lattice vertices: the shape is then interpolated linearly
          {"deformed_offgrid", deformedPoint, 0.17, 0.0},
          // a little optical blur, as real lenses have, softens cornerSubPix's own bias on sharp edges
          {"deformed_blurred_noisy", deformedPoint, 0.15, 2.0, 0.7}};
}

}  // namespace onetip::sim::testsupport
