// `onetip calibrate --pattern BOARD.yaml --input FRAMES --out C.yaml
//  [--split-x N] [--flip-left] [--flip-right]` (docs/reference.md): stereo
// calibration of the two virtual cameras; the RMS reprojection error in
// pixels is the last line printed.
#include <iomanip>
#include <iostream>

#include "calib/stereo_calibration_run.hpp"
#include "command.hpp"
#include "core/error.hpp"
#include "output_paths.hpp"

namespace onetip::tools {
namespace {

int runCalibrate(const Args& args) {
  refuseOutputClashes(args, {"out"}, {"pattern", "input"});
  refuseUnwritableOutputs(args, {"out"}, {});
  calib::StereoCalibrationRun run;
  run.pattern_path = args.get("pattern");
  run.input = args.get("input");
  run.out = args.get("out");
  run.split_x = args.getInt("split-x", -1);
  if (args.has("split-x") && run.split_x <= 0)
    throw InputError("option '--split-x': must be a positive column");
  run.flip_left = args.has("flip-left");
  run.flip_right = args.has("flip-right");
  const calib::StereoCalibrationReport report = calib::runStereoCalibration(run, std::cerr);
  const auto& r = report.result;
  std::cout << "frames used: " << report.frames_used << " of "
            << report.frames_read + report.frames_unusable << "\n"
            << std::fixed << std::setprecision(4) << "single-view RMS (px): left "
            << r.rms_left_px << ", right " << r.rms_right_px << "\n"
            << "wrote " << run.out << "\n"
            << std::setprecision(6) << "RMS reprojection error (px): " << r.rms_px << std::endl;
  return 0;
}

const CommandRegistrar registrar{Command{
    "calibrate",
    "stereo calibration of the two virtual cameras from frames showing a checkerboard in both "
    "views; prints the RMS reprojection error (px) last",
    {{"pattern", "checkerboard pattern file (rows, cols, square_mm)", false, true},
     {"input", "frames: a folder of PNG frames, a video, or another frame source", false, true},
     {"out", "calibration file to write (YAML)", false, true},
     {"split-x", "first column of the right view (default: half the frame width)", false, false},
     {"flip-left", "mirror the left half before use", true, false},
     {"flip-right", "mirror the right half before use", true, false}},
    runCalibrate}};

}  // namespace
}  // namespace onetip::tools
