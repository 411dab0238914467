#include "pipeline/frame_processor.hpp"

#include <chrono>
#include <optional>

#include "core/error.hpp"

namespace onetip::pipeline {

namespace {
using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// Why a frame cannot be split, or an empty string.
std::string frameProblem(const cv::Mat& frame, const StereoCalibration& c) {
  if (frame.empty()) return "empty frame";
  if (frame.type() != CV_8UC1) return "frame is not 8-bit grey";
  if (frame.cols != c.image_width || frame.rows != c.image_height)
    return "frame is " + std::to_string(frame.cols) + "x" + std::to_string(frame.rows) + ", the calibration says " +
           std::to_string(c.image_width) + "x" + std::to_string(c.image_height);
  return {};
}
}  // namespace

const char* toString(FrameStatus s) noexcept {
  switch (s) {
    case FrameStatus::ok: return "ok";
    case FrameStatus::reference: return "reference";
    case FrameStatus::lost: return "lost";
    case FrameStatus::skipped: break;
  }
  return "skipped";
}

void FrameProcessorOptions::validate() const {
  detector.validate();
  tracker.validate();
  triangulator.validate();
  view_shift.validate();
  pose.validate();
  if (min_markers < 3) throw InputError("frame processor: min_markers: must be at least 3");
}

struct FrameProcessor::Impl {
  StereoCalibration calib;
  MarkerPattern pattern;
  FrameProcessorOptions options;
  vision::CornerDetector detector;
  vision::GridTracker left, right;
  vision::Triangulator triangulator;
  vision::ViewShiftKeeper view_shift;
  input::PoseTracker pose;
  bool has_reference = false;
  bool last_contact = false;          // the last processed frame's contact
  std::string view_shift_report;      // this frame's, for an event
  SensorFrame S;
  MarkerField rest_S;

  Impl(const StereoCalibration& c, const MarkerPattern& p, FrameProcessorOptions o)
      : calib(c), pattern(p), options(std::move(o)), detector(options.detector), left(p, options.tracker),
        right(p, options.tracker), triangulator(c, options.triangulator),
        view_shift(c.flip_left, c.flip_right, options.view_shift), pose(options.pose) {}

  // Finds and identifies markers in both views. The rest frame is searched
  // whole and its grid built from the corners' links; later frames are
  // searched only near each marker's prediction (and around lost ones).
  std::optional<MarkerField> measure(const cv::Mat& frame, bool initialize, FrameResult& r);

  bool findMarkers(const vision::StereoViews& views, bool initialize, FrameResult& r, vision::ViewMarkers& ml,
                   vision::ViewMarkers& mr) {
    const auto t0 = Clock::now();
    vision::GridResult gl, gr;
    if (initialize) {
      std::vector<vision::Corner> cl = detector.detect(views.left.raw), cr = detector.detect(views.right.raw);
      for (auto& c : cl) c = vision::toView(c, views.left);
      for (auto& c : cr) c = vision::toView(c, views.right);
      r.times.detect = msSince(t0);
      const auto t1 = Clock::now();
      gl = left.initialize(cl, views.left);
      gr = right.initialize(cr, views.right);
      r.times.track = msSince(t1);
    } else {
      gl = left.track(views.left, detector);
      gr = right.track(views.right, detector);
      r.times.detect = gl.detect_ms + gr.detect_ms;
      r.times.track = msSince(t0) - r.times.detect;
    }
    r.found_left = gl.found;
    r.found_right = gr.found;
    if (!gl.ok() || !gr.ok()) {
      r.status = initialize ? FrameStatus::skipped : FrameStatus::lost;
      r.message = std::string(initialize ? "rest frame: " : "") + (gl.ok() ? "right view: " + gr.message
                                                                            : "left view: " + gl.message);
      return false;
    }
    ml = gl.markers;
    mr = gr.markers;
    return true;
  }
};

FrameProcessor::FrameProcessor(const StereoCalibration& calib, const MarkerPattern& pattern,
                               FrameProcessorOptions options) {
  calib.validate();
  pattern.validate();
  options.pose.marker_depth_mm = pattern.marker_depth_mm;  // the pad's, whatever the options said
  options.validate();
  if (options.min_markers > pattern.count())
    throw InputError("frame processor: min_markers: " + std::to_string(options.min_markers) + " is more than the " +
                     std::to_string(pattern.count()) + " markers of the pattern (every frame would be lost)");
  impl_ = std::make_unique<Impl>(calib, pattern, std::move(options));
}

FrameProcessor::~FrameProcessor() = default;

// The shared front half of a frame: check, split, find markers, triangulate.
// Returns the triangulated markers (L), or nothing with r.status and
// r.message saying why. Stage times are filled as they run.
std::optional<MarkerField> FrameProcessor::Impl::measure(const cv::Mat& frame, bool initialize, FrameResult& r) {
  if (std::string why = frameProblem(frame, calib); !why.empty()) {
    r.message = why;
    return std::nullopt;
  }
  const vision::StereoViews views = vision::splitViews(frame, calib);
  vision::ViewMarkers ml, mr;
  if (!findMarkers(views, initialize, r, ml, mr)) return std::nullopt;
  const auto t0 = Clock::now();
  view_shift_report.clear();
  if (!initialize && !last_contact)
    view_shift_report = view_shift.update(left.rest(), right.rest(), ml, mr).report;
  view_shift.correct(ml, mr);
  vision::TriangulationResult tri = triangulator.triangulate(ml, mr);
  r.times.triangulate = msSince(t0);
  if (tri.markers.validCount() < options.min_markers) {
    r.status = initialize ? FrameStatus::skipped : FrameStatus::lost;
    r.message = std::string(initialize ? "rest frame: " : "") + "only " + std::to_string(tri.markers.validCount()) +
                " markers triangulated";
    return std::nullopt;
  }
  return std::move(tri.markers);
}

FrameResult FrameProcessor::setReference(const cv::Mat& frame, double t) {
  Impl& m = *impl_;
  const auto start = Clock::now();
  FrameResult r;
  r.t = t;
  const std::optional<MarkerField> rest_L = m.measure(frame, true, r);
  r.times.process = msSince(start);
  if (!rest_L) return r;
  m.S = SensorFrame::fromRestMarkers(*rest_L);
  m.rest_S = m.S.toSensor(*rest_L);
  m.has_reference = true;
  m.pose.reset();
  m.view_shift.reset();
  m.last_contact = false;
  r.markers = m.rest_S;
  r.status = FrameStatus::reference;
  return r;
}

FrameResult FrameProcessor::process(const cv::Mat& frame, double t) {
  Impl& m = *impl_;
  if (!m.has_reference) return setReference(frame, t);
  const auto start = Clock::now();
  FrameResult r;
  r.t = t;
  const std::optional<MarkerField> now_L = m.measure(frame, false, r);
  if (!now_L) {
    r.times.process = msSince(start);
    return r;
  }
  r.markers = m.S.toSensor(*now_L);
  auto t0 = Clock::now();
  r.pose = m.pose.update(r.markers, m.rest_S, t);
  const double contact_and_pose = msSince(t0);
  m.last_contact = r.pose.contact;
  if (!m.view_shift_report.empty())
    r.pose.events.push_back(
        {input::EventType::error, r.pose.t, r.pose.input, r.pose.sd, r.pose.state, m.view_shift_report});
  r.times.contact = r.pose.contact_ms;
  r.times.pose = contact_and_pose - r.pose.contact_ms;
  r.status = FrameStatus::ok;
  r.times.process = msSince(start);
  return r;
}

void FrameProcessor::rezero() { impl_->pose.reset(); }
bool FrameProcessor::hasReference() const { return impl_->has_reference; }
const MarkerField& FrameProcessor::restMarkers() const { return impl_->rest_S; }
const SensorFrame& FrameProcessor::sensorFrame() const { return impl_->S; }
const StereoCalibration& FrameProcessor::calibration() const { return impl_->calib; }
const MarkerPattern& FrameProcessor::pattern() const { return impl_->pattern; }
const vision::ViewMarkers& FrameProcessor::leftViewMarkers() const { return impl_->left.current(); }
const vision::ViewMarkers& FrameProcessor::rightViewMarkers() const { return impl_->right.current(); }

}  // namespace onetip::pipeline
