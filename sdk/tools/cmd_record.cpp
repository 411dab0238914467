// `onetip record`: keeps a frame source's frames as delivered (a camera's MJPEG
// unchanged, decoded frames as lossless PNG), their indices and timestamps,
// and the calibration and pattern, as a session folder
// (capture/session_source.hpp) that replays wherever a source is taken:
// `onetip process --input SESSION` gives the live run's pose.csv.
// The session appears whole at the end; Ctrl-C or SIGTERM ends the recording
// there (a camera ends no other way) and the frames so far make the session;
// so does a full disk (exit 1, naming the cause). Until then it is recorded in
// OUT.partial.<owner>.<random> (core/atomic_file.hpp), whose session.csv
// gains a row with each frame: a run killed even by SIGKILL leaves a folder
// that `process --input` replays up to its last complete frame. That folder,
// or one whose commit failed, is never removed automatically: its path is
// printed.
#include <cstdio>
#include <filesystem>
#include <optional>

#include "capture/open_frame_source.hpp"
#include "capture/session_writer.hpp"
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
  for (const auto& kept : abandonedStaging(args.get("out"), true))
    std::fprintf(stderr, "onetip record: note: %s holds a recording of an earlier run that was killed (kept; replay it "
                 "with onetip process --input %s)\n", kept.c_str(), kept.c_str());
  const InterruptHandlers handlers;
  AtomicDir session(args.get("out"), Abandoned::keep);  // never removed once it holds a frame
  std::optional<capture::SessionWriter> writer;
  // Anything that ends the run early from here on leaves the frames so far, and says where.
  const auto keptNote = [&] {
    if (writer && writer->frames() > 0)
      std::fprintf(stderr, "onetip record: the %zu frames recorded so far are kept in %s\n", writer->frames(),
                   session.path().c_str());
    else
      session.discard();  // nothing recorded: nothing to keep
  };
  int skipped = 0, errors = 0, consecutive_errors = 0;
  std::string write_failure;
  try {
    if (have_files) {
      saveCalibration(calib, (std::filesystem::path(session.path()) / "calib.yaml").string());
      savePattern(pattern, (std::filesystem::path(session.path()) / "pattern.yaml").string());
    }
    writer.emplace(session.path());
    while (!interruptRequested() && (max_frames == 0 || writer->frames() < static_cast<size_t>(max_frames))) {
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
      try {
        writer->add(f);
      } catch (const capture::SessionWriteError& e) {  // a full disk: close the session on the frames so far
        write_failure = e.what();
        std::fprintf(stderr, "onetip record: %s; recording stopped\n", e.what());
        break;
      }
    }
  } catch (...) {
    keptNote();
    throw;
  }
  if (writer->frames() == 0) {
    session.discard();
    if (interruptRequested()) {
      std::fprintf(stderr, "onetip record: interrupted before any frame; nothing written\n");
      return kInterruptedExit;
    }
    throw InputError(write_failure.empty() ? args.get("input") + ": no usable frame to record" : write_failure);
  }
  try {
    writer->finish();
    session.commit();
  } catch (const InputError& e) {
    std::fprintf(stderr, "onetip record: %s\n", e.what());
    keptNote();
    return 1;
  }
  std::printf("%s%zu frames (%s) to %s (%d skipped, %d source errors)\n",
              interruptRequested() ? "interrupted: recorded " : !write_failure.empty() ? "write failed: recorded " : "recorded ",
              writer->frames(), encoded ? "MJPEG as delivered" : "lossless PNG", args.get("out").c_str(), skipped, errors);
  if (!write_failure.empty()) return 1;
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
