#include "calib/stereo_calibration_run.hpp"

#include "capture/open_frame_source.hpp"
#include "core/error.hpp"
#include "core/pattern.hpp"
#include "vision/calibration_board.hpp"
#include "vision/view_split.hpp"

namespace onetip::calib {

StereoCalibrationReport runStereoCalibration(const StereoCalibrationRun& run, std::ostream& log) {
  run.solver.validate();
  if (run.out.empty()) throw InputError("no output file given");
  const MarkerPattern pattern = loadPattern(run.pattern_path);
  auto source = capture::openFrameSource(run.input);

  StereoCalibrationReport report;
  StereoCalibration layout;
  bool have_layout = false;
  std::vector<vision::BoardViewPair> pairs;
  for (;;) {
    capture::Frame frame = source->next();
    if (frame.status == capture::FrameStatus::end) break;
    if (!frame.ok()) {
      ++report.frames_unusable;
      log << "frame " << frame.index << ": " << frame.message << "\n";
      continue;
    }
    ++report.frames_read;
    if (!have_layout) {
      layout.image_width = frame.grey.cols;
      layout.image_height = frame.grey.rows;
      layout.split_x = run.split_x < 0 ? frame.grey.cols / 2 : run.split_x;
      layout.flip_left = run.flip_left;
      layout.flip_right = run.flip_right;
      if (layout.split_x <= 0 || layout.split_x >= layout.image_width)
        throw InputError("--split-x " + std::to_string(layout.split_x) +
                         " lies outside the frame width " + std::to_string(layout.image_width));
      have_layout = true;
    }
    vision::StereoViews views;
    try {
      views = vision::splitViews(frame.grey, layout);
    } catch (const InputError& e) {
      ++report.frames_unusable;
      log << "frame " << frame.index << ": skipped: " << e.what() << "\n";
      continue;
    }
    auto left = vision::findCalibrationBoard(views.left, pattern);
    auto right = left ? vision::findCalibrationBoard(views.right, pattern) : std::nullopt;
    if (!left || !right) {
      log << "frame " << frame.index << ": board not found in the "
          << (!left ? "left" : "right") << " view\n";
      continue;
    }
    pairs.push_back({*left, vision::alignBoardNumbering(*left, *right, pattern.rows, pattern.cols)});
  }
  if (report.frames_read == 0)
    throw InputError("input '" + run.input + "': no readable frames");
  report.frames_used = static_cast<int>(pairs.size());
  if (pairs.empty())
    throw InputError("the " + std::to_string(pattern.rows) + " x " + std::to_string(pattern.cols) +
                     " (rows x cols) board was not found in both views of any frame");
  log << "board found in both views of " << report.frames_used << " of "
      << report.frames_read + report.frames_unusable << " frames\n";
  report.result = vision::calibrateStereo(pairs, pattern, layout, run.solver);
  report.verdict = vision::judgeCalibration(pairs, pattern, layout, run.solver, report.result, run.acceptance);
  if (!report.verdict.reasons.empty()) {
    if (!run.accept_weak) {
      std::string all;
      for (const auto& r : report.verdict.reasons) all += (all.empty() ? "" : "; ") + r;
      throw InputError("input '" + run.input + "': calibration refused: " + all +
                       " (--accept-weak writes it anyway)");
    }
    for (const auto& r : report.verdict.reasons)
      log << "warning: accepted with --accept-weak although " << r << "\n";
  }
  saveCalibration(report.result.calibration, run.out, report.result.rms_px);
  return report;
}

}  // namespace onetip::calib
