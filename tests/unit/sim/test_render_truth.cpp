// The simulator's images agree with its ground truth: every ground-truth marker
// (S, mm), projected with the ground-truth calibration file, lands within
// 0.1 px of the corner that cv::cornerSubPix finds in the rendered frame, on
// rest and on deformed frames, in both views (issue 2 acceptance).
#include <gtest/gtest.h>

#include <cstdio>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "sim/camera_rig.hpp"
#include "sim/scenario.hpp"
#include "sim/simulator.hpp"
#include "test_paths.hpp"

using namespace onetip;
using namespace onetip::sim;

namespace {
struct Errors {
  double rms = 0, max = 0;
  int n = 0;
};

// Projects S points into one view with K, D of the calibration and the view's
// pose, then mirrors into raw-frame coordinates when the half is flipped.
std::vector<cv::Point2f> project(const std::vector<cv::Point3d>& pts_S, const Eigen::Isometry3d& cam_from_S,
                                 const cv::Matx33d& K, const cv::Vec<double, 5>& D, bool flip, int width, int x0) {
  cv::Matx33d R;
  cv::Vec3d t;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) R(r, c) = cam_from_S.linear()(r, c);
    t[r] = cam_from_S.translation()[r];
  }
  cv::Vec3d rvec;
  cv::Rodrigues(R, rvec);
  std::vector<cv::Point2d> px;
  cv::projectPoints(pts_S, rvec, t, K, D, px);
  std::vector<cv::Point2f> out;
  for (const auto& p : px) out.emplace_back(static_cast<float>((flip ? width - 1 - p.x : p.x) + x0), static_cast<float>(p.y));
  return out;
}

Errors compare(const cv::Mat& frame, const std::vector<cv::Point2f>& truth) {
  std::vector<cv::Point2f> refined = truth;
  cv::cornerSubPix(frame, refined, {5, 5}, {-1, -1}, {cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 50, 1e-4});
  Errors e;
  for (size_t i = 0; i < truth.size(); ++i) {
    const double d = cv::norm(refined[i] - truth[i]);
    e.rms += d * d;
    e.max = std::max(e.max, d);
    ++e.n;
  }
  e.rms = std::sqrt(e.rms / std::max(1, e.n));
  return e;
}

void checkScenario(const std::string& name, double noise_sigma, double rms_limit) {
  Scenario sc = loadScenario(std::string(onetip::test::sourceDir()) + "/samples/scenarios/" + name + ".yaml");
  sc.image.noise_sigma = noise_sigma;
  SimulatorOptions o;
  o.frames = 9;
  Simulator sim(sc, o);
  const StereoCalibration calib = sim.calibration();
  const CameraRig rig = CameraRig::fromOptions(sc.camera);
  // The right camera's pose follows from the left one and the calibration's R, T.
  Eigen::Isometry3d right_from_left = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) right_from_left.linear()(r, c) = calib.R(r, c);
    right_from_left.translation()[r] = calib.T[r];
  }
  const Eigen::Isometry3d L_from_S = rig.left.camera_from_sensor;
  while (!sim.done()) {
    const GroundTruthFrame& f = sim.next();
    if (f.index % 4 != 0) continue;  // rest (0), pressed (4), deepest (8)
    const cv::Mat frame = sim.render();
    std::vector<cv::Point3d> pts;
    for (const auto& p : f.markers.position) pts.emplace_back(p.x(), p.y(), p.z());
    const auto left = project(pts, L_from_S, calib.K_left, calib.D_left, calib.flip_left, calib.leftWidth(), 0);
    const auto right = project(pts, right_from_left * L_from_S, calib.K_right, calib.D_right, calib.flip_right,
                               calib.rightWidth(), calib.split_x);
    for (const auto& [view, truth] : {std::pair{"left", left}, std::pair{"right", right}}) {
      const Errors e = compare(frame, truth);
      std::printf("[ measured ] %s noise %.1f frame %d %s: rms %.4f px, max %.4f px\n", name.c_str(), noise_sigma,
                  f.index, view, e.rms, e.max);
      EXPECT_LT(e.rms, rms_limit) << name << " frame " << f.index << " " << view << " max " << e.max;
      EXPECT_LT(e.max, 4 * rms_limit) << name << " frame " << f.index << " " << view;
      EXPECT_EQ(e.n, 17 * 17);
    }
  }
}
}  // namespace

TEST(RenderTruth, PressFramesNoiseFree) { checkScenario("press", 0.0, 0.1); }
TEST(RenderTruth, SlideFramesNoiseFree) { checkScenario("slide_x", 0.0, 0.1); }
TEST(RenderTruth, PressFramesAtDefaultNoise) { checkScenario("press", 2.0, 0.1); }
