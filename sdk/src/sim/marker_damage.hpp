// sim/marker_damage.hpp — markers hidden for good by a tear in the skin or
// dirt stuck to it: the spot moves with the gel, it never comes back.
//
// Which markers: the ids listed, plus round(fraction x count) others drawn
// without replacement from the seed (std::mt19937 shuffle of the remaining
// ids), so a run is reproducible and the listed ones are always hidden.
// Image level: over each hidden marker's corner, at the marker's current
// position (it follows the gel: pressed, slid, drifted), a smudge is painted
// on the rendered view before lighting and noise: a disc of `radius` squares
// (default 0.4: it covers the corner's saddle and leaves the neighbours,
// one square away, untouched) whose core is flat grey at the checker's mean
// level and whose rim (the outer 40 %) blends to the board with a smoothstep.
// A flat spot has no saddle, so no detector finds a corner there. The disc is
// round in the image (its radius in px from projecting the marker and a point
// radius mm away along S.x): dirt seen through the gel, not a printed shape.
// Field level: the hidden markers are invalid in the frame's marker field
// (GroundTruthFrame::markers.valid = 0) while their true positions stay
// filled (gt_markers.csv still lists them): a field-level consumer sees the
// same markers missing as a detector would.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "core/pattern.hpp"
#include "sim/camera_rig.hpp"

namespace onetip::sim {

struct MarkerDamageOptions {
  std::vector<int> ids;    // marker ids (row * cols + col) hidden for good
  double fraction = 0;     // further fraction of all markers hidden at random, 0..0.5
  unsigned seed = 1;       // draws that random fraction
  double radius = 0.4;     // smudge radius, in squares, 0.2..0.6
  bool enabled() const { return !ids.empty() || fraction > 0; }
  // The hidden ids, ascending; throws InputError for an id outside the pattern.
  std::vector<int> hiddenIds(const MarkerPattern& pattern) const;
  void validate() const;   // throws InputError naming the bad field
};

// Paints the smudges centred on `centres` (S, mm) into one view's grey image
// (pinhole orientation) seen by `camera`.
void paintSmudges(cv::Mat1f& grey, const VirtualCamera& camera, const std::vector<Eigen::Vector3d>& centres,
                  double radius_mm, float level);

}  // namespace onetip::sim
