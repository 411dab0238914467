// `onetip calibrate --pattern BOARD.yaml --input FRAMES --out C.yaml
//  [--split-x N] [--flip-left] [--flip-right] [--accept-weak]`
// (docs/reference.md): stereo calibration of the two virtual cameras; the RMS
// reprojection error in pixels is the last line printed. A calibration with a
// mirrored view, a misfit or too little coverage for the SDK's accuracy
// (calib/stereo_calibration_run.hpp) exits non-zero naming why, unless
// --accept-weak, which writes it with a warning line per reason.
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
  run.accept_weak = args.has("accept-weak");
  const calib::StereoCalibrationReport report = calib::runStereoCalibration(run, std::cerr);
  const auto& r = report.result;
  const auto& c = report.verdict.coverage;
  std::cout << "frames used: " << report.frames_used << " of "
            << report.frames_read + report.frames_unusable << "\n"
            << std::fixed << std::setprecision(1) << "coverage: tilts spread over " << c.tilt_spread_deg
            << " deg, corners over " << 100 * c.view_fraction << " % of the left view, sd(f)/f "
            << std::setprecision(4) << 100 * c.worst_f_sd_fraction << " %\n"
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
     {"flip-right", "mirror the right half before use", true, false},
     {"accept-weak", "write a calibration that is refused (mirrored view, misfit, too few poses), "
                     "with a warning line per reason", true, false}},
    runCalibrate}};

}  // namespace
}  // namespace onetip::tools
