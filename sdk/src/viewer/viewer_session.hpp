// viewer/viewer_session.hpp — `onetip view`: frames from a source through the
// pipeline (pipeline::FrameProcessor) and onto the screen, headless image,
// recording or all three.
//
// Input: any frame source spec (capture/open_frame_source.hpp; "sim:FILE"
// scenarios included) or "sim:virtual", the simulated sensor pressed by the
// mouse-and-keyboard finger (viewer/virtual_finger.hpp). For simulated
// inputs the calibration and pattern default to the simulator's own; other
// sources need both files. The first usable frame is the rest state.
// Output: a GLFW window, or — with a screenshot (unless `windowed`), without
// a display, or when asked — a headless EGL context drawing into an offscreen
// framebuffer. frames > 0 stops after that many drawn frames; the screenshot
// is the last one (in a window: its back buffer, read before it is shown).
// pose_out logs the 6-D input of every drawn frame (viewer/viewer_pose_log.hpp).
// Times are milliseconds on the calling thread (steady clock).
#pragma once

#include <atomic>
#include <functional>
#include <opencv2/core.hpp>
#include <string>

#include "viewer/viewer_frame.hpp"
#include "viewer/viewer_renderer.hpp"

namespace onetip::viewer {

struct ViewerOptions {
  std::string input;           // required
  std::string calib, pattern;  // required unless the input is simulated
  std::string screenshot;      // PNG of the last drawn frame (implies headless)
  std::string record;          // video (.mp4, .avi) or a folder of PNGs
  std::string pose_out;        // CSV of the 6-D input per drawn frame (+ ground truth for sim inputs)
  int frames = 0;              // 0: until the source ends or the window closes
  cv::Size window{1280, 720};
  bool headless = false;
  bool windowed = false;       // a window even with a screenshot or recording (needs a display)
  const std::atomic<bool>* stop = nullptr;  // set (e.g. by SIGINT): end after the current frame, outputs written
  ViewerRendererOptions render;
  void validate() const;       // throws InputError naming the bad option
  bool runsHeadless() const;   // offscreen rather than in a window
};

struct ViewerReport {
  int drawn = 0;                 // frames drawn
  bool headless = false;
  std::string gl;                // GL_RENDERER, GL_VERSION
  double loop_fps = 0;           // drawn frames / wall time of the loop
  double median_source_ms = 0;   // getting the frame (decode or simulate)
  double median_process_ms = 0;  // the pipeline
  double median_draw_ms = 0;     // scene building + GL drawing, finished (glFinish)
  double median_readback_ms = 0; // reading the image back (0 when not needed)
  double median_present_ms = 0;  // showing the window's frame and taking its events (0 headless)
  int skipped = 0;               // frames the source could not deliver (unreadable, wrong size, blank)
  std::string last_skipped;      // the source's message for the last of them ("frame N: why")
};

// Sees every drawn frame as the window shows it (BGR, top-down) with what it showed.
using FrameObserver = std::function<void(const cv::Mat& bgr, const ViewerFrame& frame)>;

// Throws InputError for bad options or input; std::runtime_error when no
// OpenGL 3.3 core context can be had.
ViewerReport runViewer(const ViewerOptions& options, const FrameObserver& observer = {});

// True when a window can be opened (an X11 or Wayland display is set).
bool displayAvailable();

}  // namespace onetip::viewer
