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
// Measured in the pose campaign (300 random runs, field level, the largest
// (P - d) / P of a run's enclosed peaks): a finger or a sphere alone at most
// 0.01; two fingers 0.41-0.60 in 26 of the 38 two-finger runs; a flat plate
// 0.29 and below, but 0.40 and 0.49 in two runs (a few frames each), and
// up to 0.59 at the pattern's border before the enclosure rule.
#pragma once

#include <vector>

namespace onetip::contact {

// `component`: labels from labelGridComponents (-1 outside the mask);
// `depth`: n_i per cell (mm; NaN where the marker is not measured). Returns
// labels where every component is split at its prominent valleys, numbered
// from 0 by decreasing size as labelGridComponents numbers them. A fraction
// of 1 or more splits nothing (inside the mask every depth is above the
// region cut, above zero).
std::vector<int> splitAtValleys(int rows, int cols, const std::vector<int>& component, const std::vector<double>& depth,
                                double min_prominence_fraction, int* region_count);

}  // namespace onetip::contact
