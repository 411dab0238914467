// `onetip process`: the sensing pipeline over a frame source, writing pose.csv
// (and markers.csv, timing.csv) per docs/reference.md.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

#include "capture/image_file.hpp"
#include "capture/open_frame_source.hpp"
#include "command.hpp"
#include "core/csv_table.hpp"
#include "core/error.hpp"
#include "core/pose_csv.hpp"
#include "frame_tally.hpp"
#include "interrupt.hpp"
#include "output_paths.hpp"
#include "process_outputs.hpp"
#include "sensor_notices.hpp"
#include "pipeline/frame_processor.hpp"
#include "pipeline/open_pipeline.hpp"

namespace onetip::tools {
namespace {

using Clock = std::chrono::steady_clock;

int runProcess(const Args& args) {
  refuseOutputClashes(args, {"out", "markers", "timing"}, {"calib", "pattern", "reference", "input"});
  refuseUnwritableOutputs(args, {"out", "markers", "timing"}, {});
  const std::string calib_file = args.optional("calib").value_or("");
  const std::string pattern_file = args.optional("pattern").value_or("");
  pipeline::checkRigFiles(calib_file, pattern_file);
  auto source = capture::openFrameSource(args.get("input"));
  const auto [calib, pattern] = pipeline::loadRig(calib_file, pattern_file, *source, args.get("input"));
  pipeline::FrameProcessor processor(calib, pattern);

  if (auto ref = args.optional("reference")) {
    const cv::Mat img = capture::loadGreyImage(*ref, {calib.image_width, calib.image_height});
    const pipeline::FrameResult r = processor.setReference(img);
    if (r.status != pipeline::FrameStatus::reference) throw InputError("--reference " + *ref + ": " + r.message);
  }

  ProcessOutputs outputs(args.get("out"), args.optional("markers"), args.optional("timing"));
  CsvWriter& pose = outputs.pose();
  CsvWriter* const markers = outputs.markers();
  CsvWriter* const timing = outputs.timing();

  // unreadable: frames the source could not read or decode, or that cannot be used (wrong size, blank);
  // lost: readable frames on which too few markers were found or tracked.
  int processed = 0, unreadable = 0, lost = 0, errors = 0, consecutive_errors = 0;
  std::vector<double> process_ms;
  const bool quiet = args.has("quiet");
  SensorNotices notices("process");  // the camera moved, markers hidden, ...: on stderr, quiet or not
  // Ctrl-C or SIGTERM ends the stream: the frames done so far are written (a live camera ends only this way).
  const InterruptHandlers handlers;
  while (!interruptRequested()) {
    const auto t0 = Clock::now();
    capture::Frame frame = source->next();
    const double decode_ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    if (frame.status == capture::FrameStatus::end) break;
    if (frame.status == capture::FrameStatus::error) {
      ++errors;
      std::cerr << "onetip process: frame source: " << frame.message << "\n";
      if (++consecutive_errors >= 50) throw InputError(args.get("input") + ": the source keeps failing: " + frame.message);
      continue;
    }
    consecutive_errors = 0;
    if (frame.status == capture::FrameStatus::skipped) {
      ++unreadable;
      std::cerr << "onetip process: frame " << frame.index << " skipped: " << frame.message << "\n";
      continue;
    }
    const bool first = !processor.hasReference();
    const pipeline::FrameResult r = processor.process(frame.grey, frame.timestamp_s);
    if (r.status == pipeline::FrameStatus::skipped || r.status == pipeline::FrameStatus::lost) {
      // Without a rest state nothing that follows can be measured: that is bad input.
      if (first) throw InputError(args.get("input") + ": frame " + std::to_string(frame.index) + ": " + r.message);
      (r.status == pipeline::FrameStatus::lost ? lost : unreadable) += 1;
      std::cerr << "onetip process: frame " << frame.index << " " << pipeline::toString(r.status) << ": " << r.message << "\n";
      continue;
    }
    ++processed;
    notices.report(frame.index, r.pose.events);
    pose.row(poseCsvRow(frame.index, r.pose.contact, r.pose.state, r.pose.raw, r.pose.sd));
    const std::string k = std::to_string(frame.index);
    if (markers)
      for (int id = 0; id < r.markers.size(); ++id)
        if (r.markers.valid[static_cast<size_t>(id)]) {
          const auto& p = r.markers.position[static_cast<size_t>(id)];
          markers->row({k, std::to_string(id), formatNumber(p.x()), formatNumber(p.y()), formatNumber(p.z())});
        }
    if (timing)
      for (const auto& [stage, ms] : std::vector<std::pair<const char*, double>>{
               {"decode", decode_ms}, {"detect", r.times.detect}, {"track", r.times.track},
               {"triangulate", r.times.triangulate}, {"contact", r.times.contact}, {"pose", r.times.pose},
               {"process", r.times.process}})
        timing->row({k, stage, formatNumber(ms, 4)});
    process_ms.push_back(r.times.process);
    if (!outputs.endFrame()) break;  // a write failed (a full disk): known at this frame, not after the input
    if (!quiet) {
      const Input6& v = r.pose.raw;
      std::printf("frame %5lld  %-12s dx %7.3f dy %7.3f dz %7.3f  yaw %7.2f pitch %7.2f roll %7.2f  (%d/%d markers)\n",
                  static_cast<long long>(frame.index),
                  r.status == pipeline::FrameStatus::reference ? "rest" : std::string(toString(r.pose.contact ? r.pose.state : ContactState::none)).c_str(),
                  v.dx, v.dy, v.dz, v.yaw, v.pitch, v.roll, r.markers.validCount(), pattern.count());
    }
  }
  const int delivered = processed + unreadable + lost;
  if (processed == 0) {
    if (interruptRequested()) {
      std::fprintf(stderr, "onetip process: interrupted before any frame was processed; nothing written\n");
      return kInterruptedExit;
    }
    throw InputError(args.get("input") + ": no usable frame");
  }
  // A pose.csv holding a small part of the source's frames reads like a short recording, not a failed
  // one: when more than half of the frames could not be read or used, the run fails and writes nothing.
  if (!interruptRequested() && 2 * unreadable > delivered)
    throw InputError(args.get("input") + ": " + std::to_string(unreadable) + " of " + std::to_string(delivered) +
                     " frames could not be read or used (the lines above say why); more than half, so nothing is "
                     "written");
  outputs.commit();
  if (!outputs.failure().empty()) return 1;
  std::nth_element(process_ms.begin(), process_ms.begin() + static_cast<long>(process_ms.size() / 2), process_ms.end());
  std::printf("%s %d of %d frames (%d unreadable, %d lost, %d source errors); median processing %.2f ms per frame\n",
              interruptRequested() ? "interrupted: wrote" : "processed", processed, delivered, unreadable, lost, errors,
              process_ms[process_ms.size() / 2]);
  if (unreadable > 0)
    std::fprintf(stderr, "onetip process: %d of %d frames could not be read or used and are not in %s\n", unreadable,
                 delivered, args.get("out").c_str());
  return interruptRequested() ? kInterruptedExit : 0;
}

const CommandRegistrar reg{{
    "process",
    "Run the sensing pipeline over a frame source and write the 6-D pose per frame (pose.csv), optionally the 3-D "
    "markers (S, mm) and per-stage timings. Frames are numbered by their 0-based index in the source. A frame that "
    "cannot be read or used (damaged, the wrong size, blank) is skipped, named on stderr and counted in the summary; "
    "when more than half of the frames are, the run fails (exit status 2) and writes nothing. What the sensor says "
    "about itself (the camera moved against the pad, markers hidden for good, a step limited) is printed on stderr "
    "at the frame it begins.",
    {{"calib", "calibration file (docs/reference.md); optional for sim: sources", false, false},
     {"pattern", "marker pattern file; optional for sim: sources", false, false},
     {"input", "frames: a folder of PNGs, a video file, v4l2:/dev/videoN or sim:SCENARIO.yaml", false, true},
     {"out", "pose.csv to write: frame,contact,state,dx,dy,dz,yaw,pitch,roll,sd_dx,sd_dy,sd_dz,sd_yaw,sd_pitch,sd_roll", false, true},
     {"markers", "markers.csv to write: frame,id,x,y,z (S, mm)", false, false},
     {"reference", "rest-state image (default: the first frame)", false, false},
     {"timing", "timing.csv to write: frame,stage,ms", false, false},
     {"quiet", "do not print the per-frame 6-D stream", true, false}},
    runProcess}};

}  // namespace
}  // namespace onetip::tools
