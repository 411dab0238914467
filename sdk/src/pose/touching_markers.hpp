// pose/touching_markers.hpp — the markers of a contact region that the
// finger can be touching, from the shape of the normal deformation.
//
// A convex finger pressed into the pad leaves a dimple the skin conforms to:
// over the markers it touches the normal deformation n = -u.z (mm) is a cap,
// concave (its Laplacian negative, about -2/R for a finger of radius R; zero
// under a flat plate). Around the contact the pad relaxes back to rest and
// n is convex (a half-space's 1/r tail, a Pasternak foundation's dip, whose
// 40 % region holds about three times the markers that touch). Per marker i
// of the lattice with its four neighbours j measured,
//   L_i = sum_j (n_j - n_i)      (mm; the discrete Laplacian times pitch^2),
// and with independent noise sigma on each n, L_i of a flat field has
// standard deviation sqrt(20) sigma. A marker is clearly outside the touch
// when L_i > 3 sqrt(20) sigma; every other marker is kept, and so is one
// with a neighbour missing (nothing to judge it by). A marker of the skin
// just beside the contact's edge, with a neighbour under the cap, sees the
// deformation bend down into the dimple and is kept too.
//
// That test only drops what is clearly convex. Early in a press into a
// foundation the skin beside the touch is only faintly convex (its Laplacian
// n (h / l)^2 grows with the dent n; l the foundation's length), so every
// member is kept, the fits follow that majority and the press is read short
// (by a quarter, in the median over the random scenarios on a foundation).
// The cap itself is clearly concave
// from the first frames: L = -2 h^2 / R (-0.28 mm for the shipped finger at
// 1.2 mm). So the markers with all four neighbours measured and
//   L_i < -2 * 3 sqrt(20) sigma
// (beyond the convex cut by a further 3 sigma of L, so that noise does not
// move a marker in and out of the set from frame to frame) form the cap's
// core. When that core spans an area (the smaller principal extent of its
// lattice coordinates at least core_spread_pitches: not a line), the touch is
// found directly: the core, plus the members not clearly convex whose normal
// deformation is at least the core's shallowest (a flat stretch under the same
// finger; a plate's interior inside its concave rim). The skin beside the
// touch, shallower than the cap's edge, is left out.
#pragma once

#include <cstdint>
#include <vector>

#include "contact/contact_field.hpp"
#include "contact/stick_slip_classifier.hpp"
#include "core/marker_field.hpp"

namespace onetip::pose {

// Per marker id (size of field.displacement): 1 for the `members` the finger
// can be touching, 0 for the others and for non-members.
// `rows` x `cols`: the marker lattice (id = row * cols + col; when it does not
// match the field's size every member is kept); sigma_mm: the markers' noise
// per axis; core_spread_pitches: the extent a concave core needs (marker
// pitches; 0: never use the core, only drop what is clearly convex).
std::vector<std::uint8_t> touchingMarkers(const contact::ContactField& field, const std::vector<int>& members, int rows,
                                          int cols, double sigma_mm, double core_spread_pitches);

// The cap of a small contact: the concave core above (whatever its extent:
// one or two markers at the bottom of the dimple are the touch a coarse
// pattern sees as a press begins) plus the members not clearly convex at
// least as deep as the core's shallowest marker; none when the core is empty
// (nothing is found directly) or the lattice does not match. A foundation's
// skin beside a touch of one or two markers dips by about half as much as
// the markers touched (0.13 against 0.23 mm a frame for a 6.3 mm sphere on a
// 9 x 9 pattern over a 4.6 mm foundation), is not yet clearly convex, and
// outnumbers them; the cap leaves it out.
std::vector<std::uint8_t> capMarkers(const contact::ContactField& field, const std::vector<int>& members, int rows,
                                     int cols, double sigma_mm);

// A marker the finger touches moves with it or slides over it; it cannot
// part from it along the normal while the finger presses it. When no member
// the finger can be touching (`touching`, above) is labelled stick while at
// least `min_count` of them are labelled detached (their drift from the
// anchors was along the normal, contact/stick_slip_classifier.hpp), it is the
// estimate that left them: in the foundation model a press's fits follow the
// skin beside the touch, which lags the finger, and the touching markers,
// pushed deeper than the estimate carries them, are detached. Returns those
// detached touching members measured in both frames, to stick again anchored
// where they were in `before` under the estimate then (touching, they moved
// with the finger over the frame: anchored where they are `now`, the frame's
// motion would be lost); none otherwise, and none while every measured member
// counts as touching (the test did not find the dimple's edge, so it tells
// nothing).
std::vector<int> detachedUnderTheFinger(const std::vector<int>& members, const std::vector<std::uint8_t>& touching,
                                        const std::vector<contact::MarkerLabel>& labels, const MarkerField& before,
                                        const MarkerField& now, int min_count);

}  // namespace onetip::pose
