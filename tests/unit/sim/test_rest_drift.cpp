// Rest drift (sim/rest_drift.hpp) over ten minutes of rest at 1 frame/s, then
// a press: the marker field's centroid moves by offset x g(t) and its span
// grows by 1 + expansion x g(t), g(t) = 1 - exp(-t / time_s) (measured on the
// field, not through the model's formula: the centroid of a grid symmetric
// about the pad's centre moves only by the offset, a row's span only by the
// strain); the truth never reports a contact while nothing touches although
// the drift moves markers by more than the 0.1 mm contact threshold, and does
// when the finger presses; the rendered corners follow the drifted field.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "sim/camera_rig.hpp"
#include "sim/simulator.hpp"
#include "world_test_scenes.hpp"

using namespace onetip;
using namespace onetip::sim;

namespace {
constexpr double kPress = 597;  // s: the finger arrives after ten minutes of drift

Scenario driftScene(bool drift) {
  Scenario sc = testsupport::sphereScene({{0, -1}, {kPress - 2, -1}, {kPress, 1.0}, {kPress + 3, 1.0}}, 1.0);
  if (drift) {
    sc.world.drift.expansion = 0.004;
    sc.world.drift.offset_mm = {0.08, -0.05, 0.03};
    sc.world.drift.time_s = 150;
  }
  return sc;
}

Eigen::Vector3d centroid(const MarkerField& m) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& p : m.position) sum += p;
  return sum / m.size();
}
}  // namespace

TEST(RestDrift, RestFieldExpandsAndMovesWithTheThermalTimeConstantAndIsNeverATouch) {
  const Scenario sc = driftScene(true);
  const RestDriftOptions& d = sc.world.drift;
  Simulator sim(sc);
  const MarkerField& rest = sim.restMarkers();
  const MarkerPattern p = sim.pattern();
  const int a = p.id(0, 0), b = p.id(0, p.cols - 1);  // the first row's ends
  const double span0 = (rest.position[static_cast<size_t>(b)] - rest.position[static_cast<size_t>(a)]).norm();
  double largest_motion = 0;
  int pressed = 0;
  while (!sim.done()) {
    const GroundTruthFrame& f = sim.next();
    if (f.t >= kPress - 1) {
      pressed += f.in_contact ? 1 : 0;
      continue;
    }
    const double g = 1 - std::exp(-f.t / d.time_s);
    EXPECT_LE((centroid(f.markers) - centroid(rest) - g * d.offset_mm).norm(), 1e-9) << "t " << f.t;
    const double span = (f.markers.position[static_cast<size_t>(b)] - f.markers.position[static_cast<size_t>(a)]).norm();
    EXPECT_NEAR(span / span0, 1 + d.expansion * g, 1e-12) << "t " << f.t;
    EXPECT_FALSE(f.in_contact) << "t " << f.t << ": drift is not a touch";
    for (int id = 0; id < rest.size(); ++id)
      largest_motion = std::max(largest_motion, (f.markers.position[static_cast<size_t>(id)] -
                                                 rest.position[static_cast<size_t>(id)]).norm());
  }
  EXPECT_GT(largest_motion, 0.1) << "the drift exceeds the contact threshold, so the rule's rest matters";
  EXPECT_GE(pressed, 3);
}

TEST(RestDrift, PressAfterDriftReadsTheSameDepthAsWithout) {
  Simulator drifting(driftScene(true)), steady(driftScene(false));
  while (!drifting.done()) {
    const GroundTruthFrame& f = drifting.next();
    const GroundTruthFrame& g = steady.next();
    EXPECT_EQ(f.in_contact, g.in_contact) << "t " << f.t;
    EXPECT_NEAR(f.input.dz, g.input.dz, 1e-12) << "t " << f.t;
  }
}

TEST(RestDrift, RenderedCornersFollowTheDriftedField) {
  Simulator sim(driftScene(true));
  while (sim.current().t < kPress - 3) sim.next();  // g = 0.98: the drift has all but settled
  const cv::Mat frame = sim.render();
  const CameraRig rig = CameraRig::fromOptions(sim.scenario().camera);
  for (int view = 0; view < 2; ++view) {
    const VirtualCamera& cam = view == 0 ? rig.left : rig.right;
    std::vector<cv::Point2f> drifted, still;
    for (int id = 0; id < sim.current().markers.size(); ++id) {
      Eigen::Vector2d now, then;
      cam.project(cam.camera_from_sensor * sim.current().markers.position[static_cast<size_t>(id)], now);
      cam.project(cam.camera_from_sensor * sim.restMarkers().position[static_cast<size_t>(id)], then);
      auto raw = [&](const Eigen::Vector2d& px) {
        return cv::Point2f(static_cast<float>((cam.flip ? rig.view_width - 1 - px.x() : px.x()) + view * rig.view_width),
                           static_cast<float>(px.y()));
      };
      drifted.push_back(raw(now));
      still.push_back(raw(then));
    }
    std::vector<cv::Point2f> found = drifted;
    cv::cornerSubPix(frame, found, {5, 5}, {-1, -1}, {cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 50, 1e-4});
    double sum2 = 0, moved = 0;
    for (size_t i = 0; i < found.size(); ++i) {
      sum2 += std::pow(cv::norm(found[i] - drifted[i]), 2);
      moved = std::max(moved, static_cast<double>(cv::norm(drifted[i] - still[i])));
    }
    const double rms = std::sqrt(sum2 / static_cast<double>(found.size()));
    std::printf("view %d: corners %.3f px RMS from the drifted field, which moved up to %.2f px\n", view, rms, moved);
    EXPECT_LE(rms, 0.1);
    EXPECT_GT(moved, 2.0);
  }
}
