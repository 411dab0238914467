// pose/stick_set_creep.hpp — whether a stick set creeps: slipping markers
// overtake the motion it gives the finger.
//
// A frictional skin is dragged by the finger. Relative to the finger a
// slipping marker lags, back along the way the finger came; it never runs
// ahead of it (at a reversal too: there the motion turns, and a marker still
// moving the old way lags the new one). So for the increment dT the stick set
// gives (S, mm) and every slip correspondence i (its positions a frame ago,
// b_i, and now, p_i), with t(.) the part in the pad's plane (S.x, S.y: a
// press moves markers along the normal by other rules), the lead
//   lead_i = t(p_i - dT b_i) . t(dT b_i - b_i) / |t(dT b_i - b_i)|
// is at most noise while the stick set sticks. A lead beyond the slip
// threshold means the finger went further than the stick set says: the stick
// set creeps with it, each marker within the slip threshold of a fit that
// follows them all, which a label test against that fit cannot see (the
// shipped sweep_x, rendered: at the end of the +1.5 mm stroke the stick set
// was three markers in a line; the outer two crept 0.013 mm a frame, the
// middle one still moved the finger's 0.050 mm, was labelled slip against
// their fit, and 0.2 mm were lost).
// Only markers the motion carries beyond the floor (three standard deviations
// of a frame-to-frame displacement, 3 sqrt(2) sigma) give the motion a
// direction to lead along.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "pose/stick_slip_solver.hpp"

namespace onetip::pose {

// True when some slip correspondence leads the motion by more than lead_mm
// (the slip threshold); noise_mm is the marker noise sigma.
bool slipMarkersOvertake(const Eigen::Isometry3d& stick_motion, const std::vector<SlipCorrespondence>& slip,
                         double noise_mm, double lead_mm);

}  // namespace onetip::pose
