// The front end on the simulator's scenarios (samples/scenarios, all but
// calibration), against its exact ground truth: the 3-D markers in S
// projected through the simulated cameras give each id's 2-D position in each
// view (after the flip). Ids are assigned on the rest frame and tracked over
// frames approaching each scenario's largest deformation; there, in both
// views: detection >= 99.5% of the markers in view, no id swaps, and the 2-D
// error RMS <= 0.10 px (default noise, sigma 2).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "sim/camera_rig.hpp"
#include "sim/simulator.hpp"
#include "vision/grid_tracker.hpp"
#include "test_paths.hpp"
#include "sanitizer_leg.hpp"

namespace onetip::vision {
namespace {

struct ViewCheck {
  int in_view = 0, found = 0, swapped = 0;
  double sum2 = 0;
};

void check(const ViewMarkers& m, const sim::VirtualCamera& camera, const MarkerField& truth, int width, int height,
           ViewCheck& out) {
  for (int id = 0; id < truth.size(); ++id) {
    Eigen::Vector2d px;
    if (!camera.project(camera.camera_from_sensor * truth.position[static_cast<size_t>(id)], px)) continue;
    const bool in_view = px.x() >= 12 && px.y() >= 12 && px.x() < width - 12 && px.y() < height - 12;
    out.in_view += in_view ? 1 : 0;
    if (!m.valid[static_cast<size_t>(id)]) continue;
    const cv::Point2f p = m.point[static_cast<size_t>(id)];
    const double dx = p.x - px.x(), dy = p.y - px.y(), d2 = dx * dx + dy * dy;
    if (d2 > 0.25) ++out.swapped;
    else if (in_view) ++out.found, out.sum2 += d2;
  }
}

double largestDisplacement(const MarkerField& a, const MarkerField& b) {
  double d = 0;
  for (int id = 0; id < a.size(); ++id)
    d = std::max(d, (a.position[static_cast<size_t>(id)] - b.position[static_cast<size_t>(id)]).norm());
  return d;
}

// The frames to render: the rest frame, then along the scenario's own path
// whenever some marker has moved kStepMm since the last rendered frame (a
// camera at a lower rate), up to the frame of largest deformation, returned last.
constexpr double kStepMm = 0.4;  // ~14 px in the views, a third of a square
std::vector<int> framesToRender(const sim::Scenario& scenario) {
  sim::Simulator simulator(scenario);
  std::vector<MarkerField> fields;
  int target = 0;
  double largest = -1;
  while (!simulator.done()) {
    const sim::GroundTruthFrame& f = simulator.next();
    fields.push_back(f.markers);
    const double d = largestDisplacement(f.markers, simulator.restMarkers());
    if (d > largest) largest = d, target = f.index;
  }
  double per_frame = 0;  // the largest motion between two consecutive frames (30 fps)
  for (size_t i = 1; i < fields.size(); ++i) per_frame = std::max(per_frame, largestDisplacement(fields[i], fields[i - 1]));
  std::printf("%-22s largest marker motion per 30-fps frame %.3f mm\n", scenario.name.c_str(), per_frame);
  std::vector<int> frames{0};
  for (int i = 1; i < target; ++i)
    if (largestDisplacement(fields[static_cast<size_t>(i)], fields[static_cast<size_t>(frames.back())]) > kStepMm)
      frames.push_back(i - 1 > frames.back() ? i - 1 : i);
  if (target > 0) frames.push_back(target);
  return frames;
}

TEST(SimScenarios, LargestDeformationDetectedWithoutSwaps) {
  ONETIP_SWEEP_RUNS_IN_RELEASE_ONLY();
  const std::filesystem::path dir = std::filesystem::path(onetip::test::sourceDir()) / "samples/scenarios";
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".yaml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  ASSERT_FALSE(files.empty());
  const CornerDetector detector;
  double all_sum2 = 0;
  int all_found = 0;
  for (const auto& file : files) {
    const sim::Scenario scenario = sim::loadScenario(file.string());
    if (scenario.isCalibration()) continue;
    const std::vector<int> frames = framesToRender(scenario);
    const int target = frames.back();
    const sim::CameraRig rig = sim::CameraRig::fromOptions(scenario.camera);
    sim::Simulator simulator(scenario);
    const StereoCalibration calib = simulator.calibration();
    GridTracker left(simulator.pattern()), right(simulator.pattern());
    ViewCheck views[2];
    int at = -1;
    for (int index : frames) {
      while (at < index) simulator.next(), ++at;
      const StereoViews v = splitViews(simulator.render(), calib);
      if (index == 0) {
        ASSERT_TRUE(left.initialize(v.left, detector).ok()) << file.filename();
        ASSERT_TRUE(right.initialize(v.right, detector).ok()) << file.filename();
        continue;
      }
      const GridResult l = left.track(v.left, detector), r = right.track(v.right, detector);
      if (index != target) continue;
      check(l.markers, rig.left, simulator.current().markers, v.left.width(), v.left.height(), views[0]);
      check(r.markers, rig.right, simulator.current().markers, v.right.width(), v.right.height(), views[1]);
    }
    const int in_view = views[0].in_view + views[1].in_view, found = views[0].found + views[1].found;
    const double rms = std::sqrt((views[0].sum2 + views[1].sum2) / std::max(found, 1));
    std::printf("%-22s frame %3d (%2zu rendered): found %d/%d, swapped %d, 2-D RMS %.3f px\n", file.filename().c_str(), target, frames.size(), found,
                in_view, views[0].swapped + views[1].swapped, rms);
    EXPECT_GE(found, 0.995 * in_view) << file.filename();
    EXPECT_EQ(views[0].swapped + views[1].swapped, 0) << file.filename();
    EXPECT_LE(rms, 0.10) << file.filename();
    all_sum2 += views[0].sum2 + views[1].sum2, all_found += found;
  }
  std::printf("all scenarios at their largest deformation: 2-D RMS %.3f px over %d markers\n",
              std::sqrt(all_sum2 / std::max(all_found, 1)), all_found);
}

}  // namespace
}  // namespace onetip::vision
