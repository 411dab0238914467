// `onetip demo`: the main job on the embedded default sensor. Plays a scenario
// through the simulator, runs the SDK on every rendered frame, prints the
// SDK's 6-D estimate beside the simulator's truth as it goes, and writes
// est_pose.csv, the ground truth and a contact sheet of what the camera saw.
// What the sensor says about itself goes to stderr (sensor_notices.hpp).
// The folder appears whole at the end (an existing, non-empty one is refused);
// Ctrl-C or SIGTERM stops after the current frame and writes the frames done.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "command.hpp"
#include "contact_sheet.hpp"
#include "core/atomic_file.hpp"
#include "core/csv_table.hpp"
#include "core/error.hpp"
#include "core/pose_csv.hpp"
#include "interrupt.hpp"
#include "output_paths.hpp"
#include "sensor_notices.hpp"
#include "pipeline/frame_processor.hpp"
#include "sim/simulator.hpp"

namespace onetip::tools {
namespace {

std::string vectorText(const char* label, const Input6& v) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%s dx %6.2f dy %6.2f dz %5.2f yaw %6.1f pitch %6.1f roll %6.1f", label, v.dx, v.dy,
                v.dz, v.yaw, v.pitch, v.roll);
  return buf;
}

int runDemo(const Args& args) {
  refuseOutputClashes(args, {"out"}, {"scenario"});
  refuseUnwritableOutputs(args, {}, {"out"});
  sim::Simulator sim(sim::loadScenario(args.get("scenario")));
  const std::string out_dir = args.get("out");
  // Filled under a staging folder and moved into place at the end, as `onetip sim` does: an existing
  // folder with anything in it is refused, never overwritten, and a failed run leaves nothing.
  AtomicDir staging(out_dir);
  const std::filesystem::path out(staging.path());
  pipeline::FrameProcessor processor(sim.calibration(), sim.pattern());
  CsvWriter est((out / "est_pose.csv").string(), poseCsvHeader(true));
  CsvWriter truth((out / "gt_pose.csv").string(), poseCsvHeader(false));
  ContactSheet sheet(sim.frameCount());
  double sq[6] = {0, 0, 0, 0, 0, 0};
  int both = 0;
  std::printf("%5s  %-44s | %-44s\n", "frame", "SDK estimate", "simulator truth");
  const InterruptHandlers handlers;  // SIGINT/SIGTERM: the frames done so far are written whole
  SensorNotices notices("demo");     // the camera moved, markers hidden, ...: on stderr
  while (!sim.done() && !interruptRequested()) {
    const sim::GroundTruthFrame& f = sim.next();
    const cv::Mat frame = sim.render();
    const pipeline::FrameResult r = processor.process(frame, f.t);
    const Input6 e = r.pose.raw;
    notices.report(f.index, r.pose.events);
    const bool contact = r.status == pipeline::FrameStatus::ok && r.pose.contact;
    est.row(poseCsvRow(f.index, contact, r.pose.state, e, r.pose.sd));
    truth.row(poseCsvRow(f.index, f.in_contact, f.state, f.input));
    if (contact && f.in_contact) {
      const auto a = e.asArray(), b = f.input.asArray();
      for (int i = 0; i < 6; ++i) sq[i] += (a[i] - b[i]) * (a[i] - b[i]);
      ++both;
    }
    std::printf("%5d  %-12s %5.2f %5.2f %5.2f %5.1f %5.1f %5.1f | %-12s %5.2f %5.2f %5.2f %5.1f %5.1f %5.1f\n", f.index,
                std::string(toString(contact ? r.pose.state : ContactState::none)).c_str(), e.dx, e.dy, e.dz, e.yaw,
                e.pitch, e.roll, std::string(toString(f.in_contact ? f.state : ContactState::none)).c_str(), f.input.dx,
                f.input.dy, f.input.dz, f.input.yaw, f.input.pitch, f.input.roll);
    if (sheet.wants(f.index))
      sheet.add(frame, {"frame " + std::to_string(f.index) + "  " + std::to_string(r.markers.validCount()) + " markers, " +
                            std::string(toString(contact ? r.pose.state : ContactState::none)),
                        vectorText("SDK  ", e), vectorText("truth", f.input)});
  }
  est.commit();
  truth.commit();
  sheet.save((out / "contact_sheet.png").string());
  staging.commit();
  const std::string sheet_path = (std::filesystem::path(out_dir) / "contact_sheet.png").string();
  if (both > 0) {
    const char* names[6] = {"dx", "dy", "dz", "yaw", "pitch", "roll"};
    std::printf("RMS error over %d frames in contact:", both);
    for (int i = 0; i < 6; ++i) std::printf(" %s %.3f%s", names[i], std::sqrt(sq[i] / both), i < 3 ? " mm" : " deg");
    std::printf("\n");
  }
  std::cout << (interruptRequested() ? "interrupted: " : "") << "wrote " << sheet_path
            << ", est_pose.csv and gt_pose.csv in " << out_dir << "\n";
  return interruptRequested() ? kInterruptedExit : 0;
}

const CommandRegistrar reg{{
    "demo",
    "The main job on the simulated sensor: play a scenario, run the SDK on every rendered frame, print its 6-D "
    "estimate beside the truth, write est_pose.csv, gt_pose.csv and contact_sheet.png.",
    {{"scenario", "scenario YAML file (samples/scenarios/demo_touch.yaml)", false, true},
     {"out", "output folder to create (absent or empty; nothing else is ever deleted or replaced)", false, true}},
    runDemo}};

}  // namespace
}  // namespace onetip::tools
