#include "viewer/viewer_session.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <memory>
#include <optional>
#include <vector>

#include "capture/open_frame_source.hpp"
#include "core/error.hpp"
#include "core/median.hpp"
#include "gl/gl_api.hpp"
#include "gl/headless_context.hpp"
#include "gl/offscreen_target.hpp"
#include "sim/sim_frame_source.hpp"
#include "viewer/frame_recorder.hpp"
#include "viewer/glfw_window.hpp"
#include "viewer/viewer_pose_log.hpp"
#include "viewer/virtual_finger.hpp"

namespace onetip::viewer {

namespace {
using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

constexpr const char* kVirtualInput = "sim:virtual";

// The opened input with the calibration and pattern that go with it.
struct OpenedInput {
  std::unique_ptr<capture::FrameSource> source;
  VirtualFingerSource* finger = nullptr;  // set for sim:virtual
  const sim::Simulator* simulator = nullptr;  // set for simulated inputs (ground truth)
  StereoCalibration calib;
  MarkerPattern pattern;
};

OpenedInput openInput(const ViewerOptions& o) {
  OpenedInput in;
  std::optional<StereoCalibration> sim_calib;
  std::optional<MarkerPattern> sim_pattern;
  if (o.input == kVirtualInput) {
    auto finger = std::make_unique<VirtualFingerSource>();
    in.finger = finger.get();
    in.simulator = &finger->simulator();
    sim_calib = finger->simulator().calibration();
    sim_pattern = finger->simulator().pattern();
    in.source = std::move(finger);
  } else {
    sim::registerSimFrameSource();
    in.source = capture::openFrameSource(o.input);
    if (const auto* s = dynamic_cast<const sim::SimFrameSource*>(in.source.get())) {
      in.simulator = &s->simulator();
      sim_calib = s->simulator().calibration();
      sim_pattern = s->simulator().pattern();
    }
  }
  if (!o.calib.empty()) in.calib = loadCalibration(o.calib);
  else if (sim_calib) in.calib = *sim_calib;
  else throw InputError("--calib: required for the input " + o.input + " (only simulated inputs bring their own)");
  if (!o.pattern.empty()) in.pattern = loadPattern(o.pattern);
  else if (sim_pattern) in.pattern = *sim_pattern;
  else throw InputError("--pattern: required for the input " + o.input + " (only simulated inputs bring their own)");
  return in;
}

// Where the frames are drawn: a window, or an offscreen framebuffer in a
// headless context, current on this thread for the surface's life.
struct Surface {
  std::unique_ptr<ViewerWindow> window;
  std::unique_ptr<gl::HeadlessContext> egl;
  std::unique_ptr<gl::HeadlessContext::Binding> egl_current;
  std::unique_ptr<gl::OffscreenTarget> target;
  cv::Size size;

  Surface(const ViewerOptions& o, bool headless) {
    if (headless) {
      egl = std::make_unique<gl::HeadlessContext>();
      egl_current = std::make_unique<gl::HeadlessContext::Binding>(*egl);
      target = std::make_unique<gl::OffscreenTarget>(o.window, GL_RGBA8);
      target->bind();
      size = o.window;
    } else {
      window = std::make_unique<ViewerWindow>(o.window, "onetip view — " + o.input);
      size = window->framebufferSize();
    }
  }
};
}  // namespace

bool displayAvailable() {
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x11 && *x11) || (wayland && *wayland);
}

void ViewerOptions::validate() const {
  if (input.empty()) throw InputError("--input: missing");
  if (frames < 0) throw InputError("--frames: must be >= 0");
  if (windowed && headless) throw InputError("--windowed: cannot be combined with --headless");
  if (windowed && !displayAvailable())
    throw InputError("--windowed: no display to open a window on (DISPLAY and WAYLAND_DISPLAY are unset)");
  if (window.width < 640 || window.height < 360 || window.width > 7680 || window.height > 4320)
    throw InputError("--size: must be between 640x360 and 7680x4320");
  if (runsHeadless() && input == kVirtualInput && frames == 0)
    throw InputError("--frames: needed for sim:virtual without a window (it never ends)");
  render.validate();
}

bool ViewerOptions::runsHeadless() const {
  return headless || (!screenshot.empty() && !windowed) || !displayAvailable();
}

ViewerReport runViewer(const ViewerOptions& o, const FrameObserver& observer) {
  o.validate();
  OpenedInput in = openInput(o);
  const pipeline::FrameProcessorOptions pipeline_options;
  pipeline::FrameProcessor processor(in.calib, in.pattern, pipeline_options);
  ViewerReport report;
  report.headless = o.runsHeadless();
  Surface surface(o, report.headless);
  report.gl = gl::currentGlDescription();
  ViewerRendererOptions render = o.render;
  render.working_range = pipeline_options.pose.working_range;  // the gauges' full scale
  ViewerRenderer renderer(in.calib, render);
  std::unique_ptr<FrameRecorder> recorder;
  if (!o.record.empty()) recorder = std::make_unique<FrameRecorder>(o.record, 30.0);
  std::unique_ptr<ViewerPoseLog> pose_log;
  if (!o.pose_out.empty()) pose_log = std::make_unique<ViewerPoseLog>(o.pose_out, in.simulator != nullptr, in.finger != nullptr);
  const bool need_image = observer || recorder || !o.screenshot.empty();

  ViewerFrame view;
  view.source = in.source->describe();
  if (in.finger && surface.window) view.hint = virtualFingerHelp();
  std::vector<double> source_ms, process_ms, draw_ms, readback_ms, present_ms;
  cv::Mat last;
  int consecutive_errors = 0;
  const auto loop_start = Clock::now();
  auto previous = loop_start;       // end of the last drawn frame (the frame rate)
  auto last_controls = loop_start;  // when the finger's controls were last taken (their hold time)
  for (;;) {
    if (surface.window && !surface.window->isOpen()) break;
    if (o.frames > 0 && report.drawn >= o.frames) break;
    if (o.stop && o.stop->load()) break;
    const auto t_frame = Clock::now();
    if (in.finger && surface.window) {
      in.finger->finger().apply(surface.window->takeControls(std::chrono::duration<double>(t_frame - last_controls).count()));
      last_controls = t_frame;
      if (surface.window->takeRezero()) processor.rezero();
    }
    capture::Frame frame = in.source->next();
    const double t_source = msSince(t_frame);
    if (frame.status == capture::FrameStatus::end) break;
    if (frame.status != capture::FrameStatus::ok) {
      if (frame.status == capture::FrameStatus::skipped) {
        ++report.skipped;
        report.last_skipped = "frame " + std::to_string(frame.index) + " skipped: " + frame.message;
      }
      if (++consecutive_errors >= 50) throw InputError(o.input + ": the source keeps failing: " + frame.message);
      continue;
    }
    consecutive_errors = 0;
    const bool first = !processor.hasReference();
    pipeline::FrameResult result = processor.process(frame.grey, frame.timestamp_s);
    if (first && !processor.hasReference())
      throw InputError(o.input + ": frame " + std::to_string(frame.index) + ": " + result.message);
    view.index = frame.index;
    view.camera = frame.grey;
    view.result = std::move(result);
    view.left = processor.leftViewMarkers();
    view.right = processor.rightViewMarkers();
    view.rest = processor.restMarkers();
    view.rates.source_ms = t_source;

    const auto t_draw = Clock::now();
    renderer.draw(view, surface.size);
    glFinish();
    draw_ms.push_back(msSince(t_draw));
    if (need_image) {
      const auto t_read = Clock::now();
      last = gl::readFramebufferBgr(surface.size);
      readback_ms.push_back(msSince(t_read));
    }
    view.rates.render_ms = msSince(t_draw);
    if (surface.window) {
      const auto t_present = Clock::now();
      surface.window->present();
      present_ms.push_back(msSince(t_present));
    }
    if (recorder) recorder->write(last);
    if (observer) observer(last, view);
    if (pose_log)
      pose_log->add(frame.index, view.result, in.simulator ? &in.simulator->current() : nullptr,
                    in.finger ? &in.finger->finger().pose() : nullptr);
    ++report.drawn;
    source_ms.push_back(t_source);
    process_ms.push_back(view.result.times.process);
    const double dt = std::chrono::duration<double>(Clock::now() - previous).count();
    previous = Clock::now();
    if (dt > 0) view.rates.view_fps = view.rates.view_fps == 0 ? 1.0 / dt : 0.9 * view.rates.view_fps + 0.1 / dt;
  }
  const double wall_s = std::chrono::duration<double>(Clock::now() - loop_start).count();
  if (report.drawn == 0) throw InputError(o.input + ": no frame could be shown");
  if (!o.screenshot.empty()) writePngAtomically(o.screenshot, last);
  if (recorder) recorder->finish();
  if (pose_log) pose_log->commit();
  report.loop_fps = wall_s > 0 ? report.drawn / wall_s : 0;
  report.median_source_ms = upperMedian(source_ms);
  report.median_process_ms = upperMedian(process_ms);
  report.median_draw_ms = upperMedian(draw_ms);
  report.median_readback_ms = upperMedian(readback_ms);
  report.median_present_ms = upperMedian(present_ms);
  return report;
}

}  // namespace onetip::viewer
