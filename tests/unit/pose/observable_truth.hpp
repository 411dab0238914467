// tests/unit/pose/observable_truth.hpp — the motion the pad can see, against
// which an estimate is judged (issue 40).
//
// Over a frame interval in which no marker sticks in both frames (campaign_score.hpp's
// trulySticks: the markers stuck at the end of the interval each slipped within it, or
// none sticks at all; the contact model's nodes between the markers may still stick,
// but no marker shows it), no marker moves with the finger: the pad sees neither the
// turn nor where the finger's own point goes, only the contact footprint
// (test_gross_slip_observability.cpp proves it for the turn in gross slip). There the
// observable reference holds the turn it had, follows the centroid of the true
// contact footprint in x and y (the markers whose nodes touch the indenter, at their
// true positions, S, mm) and the truth's press depth in z (the normal deformation
// shows it). Whatever offset from the truth that leaves is carried unchanged through
// the frames that follow, to the end of the contact: elsewhere the reference moves by
// the truth's own motion over the interval, T_k T_{k-1}^-1 (S), so it is the truth
// composed with a constant rigid offset, T_k O (O = identity until the first such
// interval of a contact), read as a 6-D input at the truth's c0. (Carried as a
// constant difference of the six numbers instead, a turn held in one interval and a
// large turn about another axis after it would read as a growing error: Euler angles
// do not add.)
#pragma once

#include <vector>

#include "sim_replay.hpp"

namespace onetip::poseval {

// Both frames in contact and no marker truly sticks in both: the interval's motion is unseen.
bool noMarkerSticksThrough(const ReplayFrame& before, const ReplayFrame& now);

// One entry per frame: the observable reference (mm, deg); the truth itself
// out of contact.
std::vector<Input6> observableTruth(const std::vector<ReplayFrame>& frames);

}  // namespace onetip::poseval
