// `onetip sim`: plays a simulator scenario and writes frames and ground truth.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "command.hpp"
#include "contact_sheet.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "interrupt.hpp"
#include "output_paths.hpp"
#include "sim/ground_truth_writer.hpp"

namespace onetip::tools {
namespace {

struct Interrupted {};  // thrown from the per-frame callback to unwind the writer (its staging folder goes)

int runSim(const Args& args) {
  refuseOutputClashes(args, {"out", "contact-sheet"}, {"scenario"});
  refuseUnwritableOutputs(args, {"contact-sheet"}, {"out"});
  sim::Scenario scenario = sim::loadScenario(args.get("scenario"));
  sim::SimulatorOptions options;
  options.frames = args.getInt("frames", 0);
  options.seed = args.getInt("seed", -1);
  sim::Simulator simulator(std::move(scenario), options);
  sim::WriteOptions write;
  write.field_only = args.has("field-only");
  const auto sheet_path = args.optional("contact-sheet");
  if (sheet_path && write.field_only) throw InputError("--contact-sheet needs rendered frames (drop --field-only)");
  ContactSheet sheet(simulator.frameCount());
  // The sheet's staging file is made before the first frame and moved into
  // place right after the folder: both outputs appear, or neither.
  std::unique_ptr<AtomicFile> sheet_file;
  if (sheet_path) sheet_file = std::make_unique<AtomicFile>(*sheet_path);
  const bool quiet = args.has("quiet");
  write.on_frame = [&](const sim::GroundTruthFrame& f, int) {
    if (interruptRequested()) throw Interrupted{};
    if (sheet_path && sheet.wants(f.index)) {
      char line[160];
      std::snprintf(line, sizeof line, "truth dx %.2f dy %.2f dz %.2f  yaw %.1f pitch %.1f roll %.1f", f.input.dx,
                    f.input.dy, f.input.dz, f.input.yaw, f.input.pitch, f.input.roll);
      sheet.add(simulator.render(), {"frame " + std::to_string(f.index) + "  " +
                                         std::string(toString(f.in_contact ? f.state : ContactState::none)),
                                     line});
    }
    if (quiet) return;
    std::printf("frame %4d  contact %d  %-12s  dx %7.3f dy %7.3f dz %7.3f  yaw %7.2f pitch %7.2f roll %7.2f\n", f.index,
                f.in_contact ? 1 : 0, std::string(toString(f.in_contact ? f.state : ContactState::none)).c_str(),
                f.input.dx, f.input.dy, f.input.dz, f.input.yaw, f.input.pitch, f.input.roll);
  };
  write.before_commit = [&] {
    if (!sheet_file) return;
    const std::vector<unsigned char> png = sheet.png(*sheet_path);
    std::ostream& out = sheet_file->stream();
    out.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
    if (!out.flush()) throw InputError(*sheet_path + ": write failed");
  };
  if (!quiet) std::printf("%d frames, numbered 0 to %d\n", simulator.frameCount(), simulator.frameCount() - 1);
  {
    const InterruptHandlers handlers;  // SIGINT/SIGTERM: nothing is written, the staging folder is removed
    try {
      sim::writeSimulation(simulator, args.get("out"), write);
    } catch (const Interrupted&) {
      std::fprintf(stderr, "onetip sim: interrupted; nothing written\n");
      return kInterruptedExit;
    }
  }
  if (sheet_file) {
    try {
      sheet_file->commit();
    } catch (const InputError&) {  // the folder was made by this run: take it back rather than leave half the output
      std::error_code ec;
      std::filesystem::remove_all(args.get("out"), ec);
      throw;
    }
  }
  std::cout << "wrote " << simulator.frameCount() << " frames to " << args.get("out")
            << (sheet_path ? " and the contact sheet " + *sheet_path : std::string()) << "\n";
  return 0;
}

const CommandRegistrar reg{{
    "sim",
    "Simulate the sensor (digital twin): play a scenario, write frames/ and the ground truth "
    "(gt_pose.csv, gt_markers.csv, calib.yaml, pattern.yaml).",
    {{"scenario", "scenario YAML file (samples/scenarios/*.yaml)", false, true},
     {"out", "output folder to create (absent or empty; nothing else is ever deleted or replaced)", false, true},
     {"frames", "number of frames spread over the scenario (default: duration x fps + 1)", false, false},
     {"seed", "random seed for image noise and random poses (default: the scenario's)", false, false},
     {"field-only", "write only the ground truth, no rendered frames (fast)", true, false},
     {"quiet", "do not print the per-frame ground truth", true, false},
     {"contact-sheet", "also write a PNG grid of 12 captioned frames to this path", false, false}},
    runSim}};

}  // namespace
}  // namespace onetip::tools
