#include "campaign_score.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "sim/simulator.hpp"
#include "vision/grid_tracker.hpp"

namespace onetip::bench {

ViewScore scoreView(const vision::ViewMarkers& markers, const sim::VirtualCamera& camera, const MarkerField& truth,
                    int width, int height) {
  const size_t n = static_cast<size_t>(truth.size());
  std::vector<Eigen::Vector2d> px(n);
  std::vector<std::uint8_t> projected(n, 0);
  for (size_t i = 0; i < n; ++i) projected[i] = camera.project(camera.camera_from_sensor * truth.position[i], px[i]) ? 1 : 0;
  ViewScore s;
  s.in_view.assign(n, 0);
  s.correct.assign(n, 0);
  s.gross.assign(n, 0);
  for (int id = 0; id < truth.size(); ++id) {
    const size_t i = static_cast<size_t>(id);
    if (!projected[i]) continue;
    s.in_view[i] = px[i].x() >= 12 && px[i].y() >= 12 && px[i].x() < width - 12 && px[i].y() < height - 12;
    if (!markers.valid[i]) continue;
    const int r = id / truth.cols, c = id % truth.cols;
    std::vector<double> d;
    for (const auto& [dr, dc] : {std::pair{0, 1}, {0, -1}, {1, 0}, {-1, 0}}) {
      const int rr = r + dr, cc = c + dc;
      if (rr < 0 || cc < 0 || rr >= truth.rows || cc >= truth.cols || !projected[static_cast<size_t>(rr * truth.cols + cc)]) continue;
      d.push_back((px[static_cast<size_t>(rr * truth.cols + cc)] - px[i]).norm());
    }
    std::sort(d.begin(), d.end());
    const double square = d.empty() ? 1.0 : d[d.size() / 2];
    const cv::Point2f p = markers.point[i];
    const double error = std::hypot(p.x - px[i].x(), p.y - px[i].y()) / square;
    s.max_error_sq = std::max(s.max_error_sq, error);
    (error <= kGrossSquares ? s.correct : s.gross)[i] = 1;
  }
  return s;
}

namespace {
double largestMotion(const MarkerField& a, const MarkerField& b) {
  double d = 0;
  for (int id = 0; id < a.size(); ++id)
    d = std::max(d, (a.position[static_cast<size_t>(id)] - b.position[static_cast<size_t>(id)]).norm());
  return d;
}
}  // namespace

std::vector<FrameScore> playRun(const CampaignRun& run) {
  sim::SimulatorOptions options;
  if (run.max_frames > 0) options.frames = std::min(run.max_frames, run.scenario.defaultFrameCount());
  sim::Simulator simulator(run.scenario, options);
  const StereoCalibration calib = simulator.calibration();
  const sim::CameraRig rig = sim::CameraRig::fromOptions(run.scenario.camera);
  const MarkerPattern pattern = simulator.pattern();
  const vision::CornerDetector detector;
  vision::GridTracker left(pattern), right(pattern);
  MarkerField previous;
  std::vector<FrameScore> scores;
  while (!simulator.done()) {
    const sim::GroundTruthFrame& truth = simulator.next();
    const vision::StereoViews views = vision::splitViews(simulator.render(), calib);
    const auto t0 = std::chrono::steady_clock::now();
    vision::GridResult gl, gr;
    if (truth.index == 0) {
      gl = left.initialize(views.left, detector), gr = right.initialize(views.right, detector);
      if (!gl.ok() || !gr.ok()) throw std::runtime_error("rest frame not identified: " + gl.message + " " + gr.message);
    } else {
      gl = left.track(views.left, detector), gr = right.track(views.right, detector);
    }
    FrameScore f;
    f.frame = truth.index;
    f.track_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const ViewScore sl = scoreView(gl.markers, rig.left, truth.markers, views.left.width(), views.left.height());
    const ViewScore sr = scoreView(gr.markers, rig.right, truth.markers, views.right.width(), views.right.height());
    for (int id = 0; id < pattern.count(); ++id) {
      const size_t i = static_cast<size_t>(id);
      f.gross += sl.gross[i] + sr.gross[i];
      if (!sl.in_view[i] || !sr.in_view[i]) continue;
      const bool ok = sl.correct[i] && sr.correct[i];
      ++f.markers, f.found += ok;
      if (truth.contact[i]) ++f.contact, f.contact_found += ok;
    }
    f.max_error_sq = std::max(sl.max_error_sq, sr.max_error_sq);
    f.motion_sq = truth.index == 0 ? 0.0 : largestMotion(truth.markers, previous) / pattern.square_mm;
    previous = truth.markers;
    scores.push_back(f);
  }
  return scores;
}

}  // namespace onetip::bench
