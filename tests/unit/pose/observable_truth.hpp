// tests/unit/pose/observable_truth.hpp — the motion the pad can see, against
// which an estimate is judged (issue 40).
//
// In a frame where every contact marker slips (no marker truly sticks:
// campaign_score.hpp's trulySticks; the contact model's nodes between the
// markers may still stick, but no marker shows it), no marker moves with the
// finger: the pad sees neither the turn nor where the finger's own point goes,
// only the contact footprint (test_gross_slip_observability.cpp proves it for
// the turn). There the observable reference holds the turn it had, follows the
// centroid of the true contact footprint in x and y (the markers whose nodes
// touch the indenter, at their true positions, S, mm) and the truth's press
// depth in z (the normal deformation shows it). Whatever offset from the truth
// that leaves is carried unchanged through the frames that follow, to the end
// of the contact. Everywhere else the observable reference is the truth plus
// that offset (zero until the first such frame of a contact).
#pragma once

#include <vector>

#include "sim_replay.hpp"

namespace onetip::poseval {

// A frame in contact in which no marker truly sticks.
bool everyContactMarkerSlips(const ReplayFrame& frame);

// One entry per frame: the observable reference (mm, deg); the truth itself
// out of contact.
std::vector<Input6> observableTruth(const std::vector<ReplayFrame>& frames);

}  // namespace onetip::poseval
