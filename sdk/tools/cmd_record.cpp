// `onetip record`: keeps a frame source's frames as delivered (a camera's MJPEG
// unchanged, decoded frames as lossless PNG), their indices and timestamps,
// and the calibration and pattern, as a session folder
// (capture/session_source.hpp) that replays wherever a source is taken:
// `onetip process --input SESSION` gives the live run's pose.csv.
// The session appears whole at the end; Ctrl-C or SIGTERM ends the recording
// there (a camera ends no other way) and the frames so far make the session.
#include <cstdio>
#include <filesystem>

#include "capture/open_frame_source.hpp"
#include "capture/session_source.hpp"
#include "command.hpp"
#include "core/atomic_file.hpp"
#include "core/calibration.hpp"
#include "core/error.hpp"
#include "core/pattern.hpp"
#include "interrupt.hpp"
#include "output_paths.hpp"
#include "sim/sim_frame_source.hpp"

namespace onetip::tools {
namespace {

int runRecord(const Args& args) {
  refuseOutputClashes(args, {"out"}, {"input", "calib", "pattern"});
  refuseUnwritableOutputs(args, {}, {"out"});
  if (args.has("calib") != args.has("pattern"))
    throw InputError("give both --calib and --pattern, or neither (sim: sources have their own)");
  const int max_frames = args.getInt("frames", 0);
  if (max_frames < 0) throw InputError("option '--frames': must be >= 0");
  auto source = capture::openFrameSource(args.get("input"));
  const bool encoded = source->keepEncodedFrames(true);
  StereoCalibration calib;
  MarkerPattern pattern;
  bool have_files = args.has("calib");
  if (have_files) {
    calib = loadCalibration(args.get("calib"));
    pattern = loadPattern(args.get("pattern"));
  } else if (const auto* sim = dynamic_cast<const sim::SimFrameSource*>(source.get())) {
    calib = sim->simulator().calibration();
    pattern = sim->simulator().pattern();
    have_files = true;
  }
  AtomicDir session(args.get("out"));
  if (have_files) {
    saveCalibration(calib, (std::filesystem::path(session.path()) / "calib.yaml").string());
    savePattern(pattern, (std::filesystem::path(session.path()) / "pattern.yaml").string());
  }
  capture::SessionWriter writer(session.path());
  const InterruptHandlers handlers;
  int skipped = 0, errors = 0, consecutive_errors = 0;
  while (!interruptRequested() && (max_frames == 0 || writer.frames() < static_cast<size_t>(max_frames))) {
    const capture::Frame f = source->next();
    if (f.status == capture::FrameStatus::end) break;
    if (f.status == capture::FrameStatus::error) {
      ++errors;
      std::fprintf(stderr, "onetip record: frame source: %s\n", f.message.c_str());
      if (++consecutive_errors >= 50) throw InputError(args.get("input") + ": the source keeps failing: " + f.message);
      continue;
    }
    consecutive_errors = 0;
    if (f.status == capture::FrameStatus::skipped) {
      ++skipped;
      std::fprintf(stderr, "onetip record: frame %lld skipped: %s\n", static_cast<long long>(f.index), f.message.c_str());
      continue;
    }
    writer.add(f);
  }
  if (writer.frames() == 0) {
    if (interruptRequested()) {
      std::fprintf(stderr, "onetip record: interrupted before any frame; nothing written\n");
      return kInterruptedExit;
    }
    throw InputError(args.get("input") + ": no usable frame to record");
  }
  writer.finish();
  session.commit();
  std::printf("%s%zu frames (%s) to %s (%d skipped, %d source errors)\n",
              interruptRequested() ? "interrupted: recorded " : "recorded ", writer.frames(),
              encoded ? "MJPEG as delivered" : "lossless PNG", args.get("out").c_str(), skipped, errors);
  return interruptRequested() ? kInterruptedExit : 0;
}

const CommandRegistrar reg{{
    "record",
    "Record a frame source as a session folder (frames as delivered: MJPEG unchanged, else lossless PNG; timestamps; "
    "calibration and pattern) that replays wherever a source is taken (--input SESSION).",
    {{"input", "frames: v4l2:/dev/videoN, sim:SCENARIO.yaml, a folder or a video file", false, true},
     {"out", "session folder to create (absent or empty)", false, true},
     {"calib", "calibration file to keep with the session (sim: sources: the simulator's)", false, false},
     {"pattern", "marker pattern file to keep with the session (sim: sources: the simulator's)", false, false},
     {"frames", "stop after this many recorded frames (default: the end of the source, or Ctrl-C)", false, false}},
    runRecord}};

}  // namespace
}  // namespace onetip::tools
