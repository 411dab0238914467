// `onetip collect`: records a haptic renderer dataset with the sensor inside
// the display (calib/haptic_collection.hpp), here the simulated display with a
// simulated sensor. A progress bar with an ETA goes to stderr; Ctrl-C (SIGINT, or SIGTERM)
// stops after the current row, and running the same command again resumes from
// the progress file. Exit status: 0 complete (dataset written), 1 stopped
// before the end (SIGINT or --max-rows; resumable), 2 bad input.
#include <cstdio>
#include <iostream>
#include <memory>

#include "calib/haptic_collection.hpp"
#include "command.hpp"
#include "core/error.hpp"
#include "haptics/biotac_like_sensor.hpp"
#include "haptics/onetip_contact_sensor.hpp"
#include "interrupt.hpp"
#include "output_paths.hpp"

namespace onetip::tools {
namespace {

std::unique_ptr<haptics::TactileSensorModel> makeSensor(const std::string& name, double noise) {
  if (name == "biotac") {
    haptics::BiotacLikeOptions o;
    o.noise_counts = noise;
    return std::make_unique<haptics::BiotacLikeSensor>(o);
  }
  if (noise != 0.0) throw InputError("option '--noise': only the biotac sensor has a noise model");
  if (name == "onetip") return std::make_unique<haptics::OnetipContactSensor>();
  throw InputError("option '--sensor': '" + name + "' is not one of biotac, onetip");
}

int runCollect(const Args& args) {
  refuseOutputClashes(args, {"out", "progress-file"}, {});
  refuseUnwritableOutputs(args, {"out", "progress-file"}, {});
  calib::CollectionOptions options;
  options.step_deg = args.getDouble("step", 3.0);
  options.out_path = args.get("out");
  options.progress_path = args.optional("progress-file").value_or("");
  options.max_new_rows = args.getInt("max-rows", -1);
  if (options.max_new_rows < -1) throw InputError("option '--max-rows': must be >= 0");
  options.validate();
  const auto sensor = makeSensor(args.optional("sensor").value_or("biotac"), args.getDouble("noise", 0.0));
  const haptics::PlatformKinematics device;
  calib::SimulatedRig rig(device, *sensor);

  const bool quiet = args.has("quiet");
  double last_drawn = -1.0;
  calib::CollectionProgress last;
  auto draw = [&](const calib::CollectionProgress& p) {
    last = p;
    if (quiet || (p.elapsed_s - last_drawn < 0.25 && p.done < p.total)) return;
    last_drawn = p.elapsed_s;
    std::fprintf(stderr, "\r%s", calib::formatProgressBar(p).c_str());
  };
  calib::CollectionResult result;
  {
    const InterruptHandlers handlers;  // SIGINT/SIGTERM: stop after the current row, resumable
    result = calib::collectDataset(rig, options, interruptFlag(), draw);
  }
  if (!quiet && last_drawn >= 0.0) std::fprintf(stderr, "\r%s\n", calib::formatProgressBar(last).c_str());
  if (result.status == calib::CollectionResult::Status::interrupted) {
    std::cerr << "onetip collect: stopped at " << result.rows << "/" << result.total << " rows ("
              << options.progressPath() << "); run the same command again to resume\n";
    return 1;
  }
  std::cout << "wrote " << result.rows << " rows (" << result.resumed << " resumed) to " << options.out_path << "\n";
  return 0;
}

const CommandRegistrar kCollect{Command{
    "collect",
    "record a haptic dataset: sweep the display's motor grid with the sensor inside it (resumable)",
    {{"out", "dataset to write: .csv (m1,m2,m3,s1,...,sN) or .bin (binary)", false, true},
     {"step", "grid step in degrees, [1.65, 165] (default 3: 55^3 = 166,375 configurations; at most 100^3)", false, false},
     {"sensor", "simulated sensor: biotac (20 channels, default) or onetip (5 x 5 marker displacements)", false,
      false},
     {"noise", "biotac sensor noise, counts (default 0: deterministic, resumes reproduce exactly)", false, false},
     {"progress-file", "append-only progress file (default OUT.progress)", false, false},
     {"max-rows", "stop after this many new rows (resume later)", false, false},
     {"quiet", "no progress bar", true, false}},
    runCollect}};

}  // namespace
}  // namespace onetip::tools
