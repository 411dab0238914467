// core/pose_csv.hpp — the columns and rows of pose.csv (CONVENTIONS.md,
// docs/reference.md), shared by every writer of that format: `onetip process`
// (pose.csv), `onetip demo` (est_pose.csv, gt_pose.csv), `onetip view
// --pose-out` and `onetip sim` (gt_pose.csv).
//
//   frame,contact,state,dx,dy,dz,yaw,pitch,roll   the 6-D input (S; mm, deg);
//                                                 state is none out of contact
//   sd_dx,sd_dy,sd_dz,sd_yaw,sd_pitch,sd_roll     one standard deviation of each
//                                                 component (mm, deg; 0 out of contact)
//
// An estimate has all fifteen columns. The simulator's ground truth has only
// the first nine: it is exact, it has no deviation to report, and a reader
// that knows the nine reads estimate and truth alike.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "onetip/types.hpp"

namespace onetip {

// The header: the nine columns of the 6-D input, then the six sd columns when with_sd.
std::vector<std::string> poseCsvHeader(bool with_sd);

// The nine cells of a frame (truth): frame, contact 0/1, state (none when not
// in contact), then dx..roll formatted as formatNumber does.
std::vector<std::string> poseCsvRow(std::int64_t frame, bool contact, ContactState state, const Input6& v);

// The fifteen cells of an estimate: the nine, then sd_dx..sd_roll as given.
std::vector<std::string> poseCsvRow(std::int64_t frame, bool contact, ContactState state, const Input6& v,
                                    const Input6& sd);

}  // namespace onetip
