// `onetip view`: the viewer (viewer/viewer_session.hpp) — live in a window, or
// headless with --screenshot (the last frame drawn) and/or --record; --windowed
// keeps the window with them, --pose-out logs the 6-D input per frame.
#include <cstdio>
#include <filesystem>
#include <string>

#include "command.hpp"
#include "core/error.hpp"
#include "interrupt.hpp"
#include "output_paths.hpp"
#include "viewer/viewer_session.hpp"

namespace onetip::tools {
namespace {

cv::Size parseSize(const std::string& text) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x')
    throw InputError("--size " + text + ": expected WIDTHxHEIGHT, e.g. 1280x720");
  return {w, h};
}

int runView(const Args& args) {
  refuseOutputClashes(args, {"screenshot", "record", "pose-out"}, {"input", "calib", "pattern"});
  refuseUnwritableOutputs(args, {"screenshot", "pose-out"}, {});
  if (const auto record = args.optional("record")) {  // a video file, or a folder for a PNG sequence
    const std::string ext = std::filesystem::path(*record).extension().string();
    if (ext == ".mp4" || ext == ".avi")
      requireWritableFile("--record", *record);
    else
      requireCreatableFolder("--record", *record);
  }
  viewer::ViewerOptions o;
  o.input = args.get("input");
  o.calib = args.optional("calib").value_or("");
  o.pattern = args.optional("pattern").value_or("");
  o.screenshot = args.optional("screenshot").value_or("");
  o.record = args.optional("record").value_or("");
  o.frames = args.getInt("frames", 0);
  o.pose_out = args.optional("pose-out").value_or("");
  o.headless = args.has("headless");
  o.windowed = args.has("windowed");
  if (auto s = args.optional("size")) o.window = parseSize(*s);
  const InterruptHandlers handlers;  // SIGINT/SIGTERM: stop after the current frame, finish the outputs
  o.stop = interruptFlag();
  const viewer::ViewerReport r = viewer::runViewer(o);
  std::printf("drew %d frames %s on %s: %.1f frames/s overall; median per frame: source %.2f ms, pipeline %.2f ms, "
              "draw %.2f ms, read-back %.2f ms, present %.2f ms\n",
              r.drawn, r.headless ? "headless" : "in a window", r.gl.c_str(), r.loop_fps, r.median_source_ms,
              r.median_process_ms, r.median_draw_ms, r.median_readback_ms, r.median_present_ms);
  if (!o.screenshot.empty()) std::printf("screenshot: %s\n", o.screenshot.c_str());
  if (r.skipped > 0)
    std::fprintf(stderr, "onetip view: %d frames could not be read or used and were not shown (last: %s)\n", r.skipped,
                 r.last_skipped.c_str());
  return interruptRequested() ? kInterruptedExit : 0;
}

const CommandRegistrar reg{{
    "view",
    "Show what the sensor sees: camera frame with markers, deformation field, contact and stick/slip, the 6-D input "
    "and timings (OpenGL 3.3; a window, or headless with --screenshot). --input sim:virtual: a finger moved by mouse "
    "and keyboard.",
    {{"input", "frames: sim:SCENARIO.yaml, sim:virtual, a folder of PNGs, a video file or v4l2:/dev/videoN", false, true},
     {"calib", "calibration file (default for sim: inputs: the simulator's)", false, false},
     {"pattern", "marker pattern file (default for sim: inputs: the simulator's)", false, false},
     {"screenshot", "PNG of the last frame drawn; runs headless unless --windowed", false, false},
     {"frames", "stop after this many frames (default: when the input ends)", false, false},
     {"record", "record what is shown: OUT.mp4 / OUT.avi, or a folder to create (absent or empty) for a PNG sequence",
      false, false},
     {"size", "window size WIDTHxHEIGHT (default 1280x720)", false, false},
     {"pose-out", "CSV of the 6-D input per drawn frame: frame,contact,state,dx,dy,dz,yaw,pitch,roll, then for sim "
                  "inputs the ground truth gt_contact,gt_dx..gt_roll, for sim:virtual the finger's pose finger_x..finger_roll",
      false, false},
     {"headless", "draw offscreen even when a display is available", true, false},
     {"windowed", "draw in a window even with --screenshot (needs a display)", true, false}},
    runView}};

}  // namespace
}  // namespace onetip::tools
