// vision/calibration_handedness.hpp — is either view of a stereo calibration
// mirrored (a view's flip missing, or given where the optics need none)?
//
// What can be observed. A mirror reverses an image's handedness. A checkerboard
// is no help inside one view: a board with an even number of inner corners
// along either side, or a square one, is its own mirror image, and an odd x odd
// board's chirality depends on which colour was printed at its first corner,
// which no pattern file states. So each view's board is numbered right-handed
// in the image (calibration_board.hpp) and the handedness is read from the
// stereo geometry instead, in two steps:
//  1. The views agree. Both views see the same face of the board, so the map
//     from the left view's board to the right view's preserves orientation. If
//     one view is mirrored, the right-handed numbering of that view names each
//     corner by its mirror image: every pose still fits its own view, but no
//     single (R, T) carries the left camera's board onto the right camera's
//     for boards at different tilts or places, and the stereo residual grows
//     far beyond the single-view ones. Solving again with the right view
//     mirrored then fits; which view was wrong is decided by step 2.
//  2. The baseline points right. With both views mirrored the geometry is
//     self-consistent (the mirror image of the true rig: same RMS), but the
//     mirror turns the left camera's x axis, so the right view's camera centre
//     C_R = -R^T T lands on the left camera's -x side. A side-by-side image
//     puts the view from the right in the right half (OpenCV's sample pairs:
//     C_R.x = +83 mm; the simulated mirror rig: about +24 mm), so C_R.x < 0 means
//     both views are mirrored.
// What it cannot detect: step 1 needs at least two board poses that differ in
// tilt or place (one pose, or poses differing by a shift along one of the
// board's axes only, fit either way; calibration_acceptance.hpp refuses
// those); step 2 assumes the side-by-side layout, so a rig whose optics show
// the right camera's view in the left half is reported as mirrored (accept it
// with --accept-weak, or swap its views).
#pragma once

#include <string>
#include <vector>

#include "core/calibration.hpp"
#include "core/pattern.hpp"
#include "vision/stereo_calibration.hpp"

namespace onetip::vision {

struct HandednessCheck {
  double baseline_x_mm = 0.0;  // C_R.x in the left camera frame (mm); > 0 expected
  bool left_mirrored = false, right_mirrored = false;
  // One line naming the mirrored view(s) and the flag to change; empty when
  // neither is.
  std::string problem;
};

// `result` is calibrateStereo(pairs, pattern, layout, options). When its RMS
// exceeds `max_rms_px`, the views are solved again with the right view
// mirrored; a fit within max_rms_px then means the views disagree.
HandednessCheck checkHandedness(const std::vector<BoardViewPair>& pairs, const MarkerPattern& pattern,
                                const StereoCalibration& layout, const StereoCalibrationOptions& options,
                                const StereoCalibrationResult& result, double max_rms_px);

}  // namespace onetip::vision
