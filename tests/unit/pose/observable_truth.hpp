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
//
// Issue 40's judge stops there: one marker that sticks through an interval
// counts as seeing the whole motion. Its own item 2 says more: a stick set
// fixes only some directions (one marker fixes its point, not the turn about
// it; a line of markers not the turn about the line). The stricter judge,
// UnseenMotion::unfixed_directions, also holds those. Over an interval whose
// sticking markers (true positions q_i at frame k-1, centroid m) do not fix
// every direction, the truth's increment D, as a turn theta and a move t of m,
// keeps only its fixed part: t and theta less its unfixed components, so the
// sticking markers move exactly as in the truth while the turn they cannot
// see is held. Which directions are fixed is the SDK's own rule
// (pose/pose_uncertainty.hpp: stickInformation, about m, where rotations and
// moves decouple) for markers with independent noise sigma per axis per
// frame (an interval's information sum_i J_i^T J_i / (2 sigma^2)): a turn is
// fixed when its sd at the set's radius is within the estimator's slip
// threshold, slip_sigmas * sigma (pose/adaptive_pose_options.hpp: the drift
// that tells a marker that moves with the finger from one that does not).
#pragma once

#include <vector>

#include "sim_replay.hpp"

namespace onetip::poseval {

// What the judge takes as unseen: issue 40's intervals in which no marker sticks through (no_marker), or also
// the directions the markers that stick through do not fix (unfixed_directions; see above).
enum class UnseenMotion { no_marker, unfixed_directions };

struct ObservableTruthOptions {
  UnseenMotion unseen = UnseenMotion::no_marker;
  double noise_mm = 0.0006;  // (0, 1] mm: per-axis marker noise (unfixed_directions only)
};

// Both frames in contact and no marker truly sticks in both: the interval's motion is unseen.
bool noMarkerSticksThrough(const ReplayFrame& before, const ReplayFrame& now);

// One entry per frame: the observable reference (mm, deg); the truth itself
// out of contact.
std::vector<Input6> observableTruth(const std::vector<ReplayFrame>& frames, const ObservableTruthOptions& options = {});

}  // namespace onetip::poseval
