// contact/finger_valleys.hpp — one contact region per finger: a connected
// region whose normal deformation has two prominent peaks is split along the
// valley between them.
//
// Two fingers a few millimetres apart press one connected area above the
// region cut (contact_analyzer.hpp) once the pad's deformation between them
// passes it; a pose estimator that follows that merged region reads the
// other finger's motion as its own. One finger's deformation n_i = -u_i.z
// has one peak (the pad smooths a convex indenter's imprint); noise and
// tracker errors add bumps of the noise's size.
//
// Flooding (a watershed by decreasing depth on the 8-neighbour grid):
// markers are taken deepest first. A marker with no taken neighbour starts a
// basin whose peak is its depth; one whose taken neighbours belong to
// several basins is a saddle at its depth d. There a basin with the lower
// peak P stays apart only when
//   - it is prominent: P - d >= min_prominence_fraction x P, and
//   - its peak is a maximum of the field, not only of what the pattern shows:
//     all eight neighbours of the peak marker are on the grid and measured
//     (a flat plate's imprint rises to the pattern's border, whose markers
//     are then peaks of the grid alone);
// else it joins the basin of the deeper peak. The saddle marker joins the
// basin of its deepest taken neighbour. Lower saddles between the same two
// basins only deepen the valley, so the first meeting decides. Scale free:
// the fraction is of the lower peak's own depth (mm cancel), as the region
// cut is a fraction of the deepest. Cost: a sort of the masked markers.
//
// Measured over 300 random scenarios (docs/pose, "Campaign"; the largest
// (P - d) / P of a run's enclosed peaks): a finger or a sphere alone at most
// 0.01; two fingers 0.41-0.60 in 26 of the 38 two-finger runs; a flat plate
// 0.29 and below, but 0.40 and 0.49 in two runs (a few frames each), and
// up to 0.59 at the pattern's border without the enclosure rule.
#pragma once

#include <cstdint>
#include <vector>

namespace onetip::contact {

// `mask`: the cells to label (1) per cell; `depth`: n_i per cell (mm; NaN
// where the marker is not measured). Returns labels where every 8-connected
// component of the mask is split at its prominent valleys, numbered from 0 by
// decreasing size as labelGridComponents numbers them (-1 outside the mask).
// A fraction of 1 or more splits nothing (inside the mask every depth is
// above the region cut, above zero).
std::vector<int> splitAtValleys(int rows, int cols, const std::vector<std::uint8_t>& mask,
                                const std::vector<double>& depth, double min_prominence_fraction, int* region_count);

// One region per finger, each cut at a fraction of its own peak: the
// markers whose `depth` (mm, the region measure: normal deformation or
// modulus) reaches min(floor, region_fraction x the deepest `normal`) are
// split into fingers (8-connected components, then splitAtValleys on
// `depth`); finger f keeps its markers whose depth reaches
// cut_f = region_fraction x P_f, P_f the largest `normal` (|u_i.z|, mm) among
// its markers, in 8-connected pieces. `floor` is the contact threshold: a
// finger counts from where its imprint is a touch. With one finger this is
// the single global cut, region_fraction x the deepest. A shallow
// finger beside a deep one keeps its region instead of falling below the deep
// one's cut, and so does a finger lifting off while another stays, until its
// imprint falls below the floor. Of 33 handovers in the random scenarios (a
// tracked finger lifting while another stays), the estimator's new contact
// begins in the truth's frame in 9 (3 under one global cut) and 1-3 frames
// early in 15: the truth ends a contact only when the finger touches no node. Returns
// labels numbered by decreasing size; `cuts` (per label, mm) receives each
// region's cut.
std::vector<int> labelFingerRegions(int rows, int cols, const std::vector<double>& depth,
                                    const std::vector<double>& normal, double floor, double region_fraction,
                                    double min_prominence_fraction, std::vector<double>& cuts, int* region_count);

}  // namespace onetip::contact
