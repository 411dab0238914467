// calib/stereo_calibration_run.hpp — the stereo calibration program: frames
// of a checkerboard target in, a calibration file out (`onetip calibrate`).
//
// Reads every frame of `input` (any frame source spec: a folder of PNG
// frames, a video, "sim:calibration.yaml", ...), splits each into its two
// views (split_x, default half the frame width; flips as given), finds the
// whole board in both views (vision/calibration_board.hpp), skips frames
// where either view misses it, calibrates (vision/stereo_calibration.hpp)
// judges it (vision/calibration_acceptance.hpp: a mirrored view, a misfit or
// poses that leave the focal length loose) and writes the calibration file
// atomically (core saveCalibration, with rms_px). A refused calibration is an
// InputError naming every reason, unless accept_weak: then each reason is a
// "warning:" line in `log` and the file is written. Progress and the count of
// frames used go to `log`.
// Bad input (missing pattern file, input that cannot be opened, no readable
// frame, frames of different sizes, the board found in too few frames)
// throws InputError before anything is written.
#pragma once

#include <ostream>
#include <string>

#include "vision/calibration_acceptance.hpp"
#include "vision/stereo_calibration.hpp"

namespace onetip::calib {

struct StereoCalibrationRun {
  std::string pattern_path;  // pattern file (rows, cols, square_mm)
  std::string input;         // frame source spec
  std::string out;           // calibration file to write
  int split_x = -1;          // -1: half the frame width
  bool flip_left = false, flip_right = false;
  bool accept_weak = false;  // write a refused calibration, with warnings
  vision::StereoCalibrationOptions solver;
  vision::CalibrationAcceptanceOptions acceptance;
};

struct StereoCalibrationReport {
  int frames_read = 0;        // frames decoded
  int frames_unusable = 0;    // skipped by the source or of the wrong size
  int frames_used = 0;        // board found in both views
  vision::StereoCalibrationResult result;
  vision::CalibrationVerdict verdict;
};

StereoCalibrationReport runStereoCalibration(const StereoCalibrationRun& run, std::ostream& log);

}  // namespace onetip::calib
