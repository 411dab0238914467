// tests/unit/pose/contact_events.hpp — when contacts begin and end, the
// estimate's against the simulator's ground truth (issue 38's acceptance:
// a contact ends within 2 frames of the truth's lift-off, and no contact
// begins while nothing touches).
//
// Frames are indices into a replay. A contact begins at the first frame in
// contact and ends at the first frame out of it. For each truth lift-off the
// end lag is the estimate's first contact end at or after the truth's onset
// of that contact, minus the truth's end, in frames (positive: late); a
// contact the estimate still holds at the end of the run lags to the run's
// end. An onset is untouched when no marker's node touches an indenter in
// its frame (a recovering or drifting pad, noise): a false onset. An onset
// in a frame where a finger touches below the truth's contact threshold (a
// finger landing on a gel that still recovers) is not false.
#pragma once

#include <vector>

#include "sim_replay.hpp"

namespace onetip::poseval {

constexpr int kLateEndFrames = 2;  // issue 38: within 2 frames of the truth's lift-off

struct ContactEvents {
  std::vector<int> truth_onset, truth_end, estimate_onset, estimate_end;  // frames
  std::vector<int> end_lag;                                               // per truth end (frames; see above)
  int onsets_untouched = 0;                                               // false onsets
  int lateEnds() const;     // truth ends the estimate follows more than kLateEndFrames late
  int worstEndLag() const;  // the largest end lag (0 without a lift-off)
};

ContactEvents contactEvents(const std::vector<ReplayFrame>& frames);

}  // namespace onetip::poseval
