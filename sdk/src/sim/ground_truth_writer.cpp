#include "sim/ground_truth_writer.hpp"

#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "core/atomic_file.hpp"
#include "core/csv_table.hpp"
#include "core/error.hpp"
#include "core/pose_csv.hpp"

namespace onetip::sim {

namespace fs = std::filesystem;

namespace {
std::string frameName(int index) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%06d.png", index);
  return buf;
}
}  // namespace

void writeSimulation(Simulator& sim, const std::string& out_dir, const WriteOptions& options) {
  AtomicDir staging(out_dir);
  const fs::path dir(staging.path());
  std::error_code ec;
  if (!fs::create_directory(dir / "frames", ec) || ec)
    throw InputError(out_dir + ": cannot create the output folder (" + ec.message() + ")");

  saveCalibration(sim.calibration(), (dir / "calib.yaml").string());
  savePattern(sim.pattern(), (dir / "pattern.yaml").string());
  CsvWriter pose((dir / "gt_pose.csv").string(), poseCsvHeader(false));
  CsvWriter markers((dir / "gt_markers.csv").string(), {"frame", "id", "x", "y", "z", "contact", "slip"});
  const int n = sim.frameCount();
  while (!sim.done()) {
    const GroundTruthFrame& f = sim.next();
    const std::string k = std::to_string(f.index);
    pose.row(poseCsvRow(f.index, f.in_contact, f.state, f.input));
    for (int id = 0; id < f.markers.size(); ++id) {
      const auto& p = f.markers.position[static_cast<size_t>(id)];
      markers.row({k, std::to_string(id), formatNumber(p.x()), formatNumber(p.y()), formatNumber(p.z()),
                   f.contact.empty() ? "0" : std::to_string(f.contact[static_cast<size_t>(id)]),
                   f.slip.empty() ? "0" : std::to_string(f.slip[static_cast<size_t>(id)])});
    }
    if (!options.field_only) {
      const std::string png = (dir / "frames" / frameName(f.index)).string();
      if (!cv::imwrite(png, sim.render())) throw InputError(png + ": cannot write the frame");
    }
    if (options.on_frame) options.on_frame(f, n);
  }
  pose.commit();
  markers.commit();
  if (options.before_commit) options.before_commit();
  staging.commit();
}

}  // namespace onetip::sim
