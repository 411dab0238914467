// pose/anchored_fit.hpp — the finger's motion from its sticking markers.
//
// Each stick marker i has an anchor a_i in the finger's frame
// (contact/stick_slip_classifier.hpp); under the previous pose estimate T its
// reference is T a_i, and the motion dT maps those references onto the
// markers' positions p_i now (S, mm). The fit is trimmed of markers drifting
// beyond the slip threshold, those lagging back towards their rest position
// first (rigid_fit.hpp: a ring starting to slip would otherwise drag the fit
// until the sticking core looks like the outlier), and robust (Cauchy scale).
// What the kept set can fix:
//   smaller principal x-y extent >= min_spread        -> a general rotation;
//   else a thin set whose turn is evidenced (below)   -> a general rotation;
//   else larger extent >= min_spread (a line)         -> a rotation about S.z;
//   else                                               -> a translation only.
// A fitted rotation smaller than `significance` times its noise
// sqrt(2) sigma / (extent sqrt(n)) is not applied (a real rotation keeps
// growing against the anchors until it is significant; noise does not).
// A thin set's turn is evidenced (thinSetTurnEvidenced) when every kept marker
// lies within thin_rigidity_sigmas sigma of the fitted motion (it moves as one
// body, to the noise: a stripe at the edge of a shrinking stick region that
// begins to slip does not) and the turn's component about the set's own line
// (its larger principal axis), the one its smaller extent e fixes worst,
// reaches thin_turn_significance times that component's noise
// sqrt(2) sigma / (e sqrt(n)). By that formula, at 0.0006 mm, a 2 x 2 block of
// a 9 x 9 pattern (e = 1.2 mm, half a pitch) rolling 0.46 deg a frame is 23
// of those sigmas, and the 0.1-0.15 deg that a twist's slipping edge stripe
// fakes (e = 0.52 mm, 4-5 markers; decision record 0008) 2-3.
#pragma once

#include <cstdint>
#include <vector>

#include "contact/contact_field.hpp"
#include "contact/stick_slip_classifier.hpp"
#include "core/marker_field.hpp"
#include "pose/adaptive_pose_options.hpp"
#include "pose/rigid_fit.hpp"

namespace onetip::pose {

// Noise sigmas (pose/adaptive_pose_options.hpp) a fitted rotation must show before it is applied.
struct RotationTests {
  double significance = 1.0;            // any set: the whole turn against its noise
  double thin_turn_significance = 5.0;  // a thin set: its turn about its own line against that turn's noise
  double thin_rigidity_sigmas = 3.0;    // a thin set: every kept marker's residual (3-D, mm) within this many sigma
};

// The thin-set test above for the fit `fit` of `from` onto `to` (S, mm), `extent` = planarExtent(from),
// sigma = noise_mm per axis.
bool thinSetTurnEvidenced(const RigidFit& fit, const std::vector<Eigen::Vector3d>& from,
                          const std::vector<Eigen::Vector3d>& to, const PlanarExtent& extent, double noise_mm,
                          const RotationTests& tests);

struct AnchoredFit {
  RigidFit fit;
  bool rotation_supported = false;  // the kept set fixes a general rotation
};

// `ids` (stick markers) becomes the kept set.
AnchoredFit fitAnchored(const contact::StickSlipClassifier& classifier, const contact::ContactField& field,
                        std::vector<int>& ids, const MarkerField& now, const Eigen::Isometry3d& pose,
                        const EstimatorThresholds& thresholds, const RotationTests& tests);

// The same, for a contact whose cap (`cap`, per marker id:
// touching_markers.hpp's capMarkers; empty or all zero: fitAnchored as is)
// must carry the fit: when the trim drops most of the cap's markers among
// `ids` (more than half), the skin beside the touch carried the fit (in a
// press it dips by about half as much as the touch and outnumbers it, so the
// touch looks like the outlier), and the fit is redone over the cap's
// markers among `ids` alone, which fix what their spread fixes (a
// translation, for one or two). A cap marker trimmed alone is one beginning
// to move off the finger, as any other; the fit stands (refitting over the
// rest of a cap too thin to fix a turn would drop the turn of a finger that
// rolls as it presses).
AnchoredFit fitAnchoredOnTheCap(const contact::StickSlipClassifier& classifier, const contact::ContactField& field,
                                std::vector<int>& ids, const std::vector<std::uint8_t>& cap, const MarkerField& now,
                                const Eigen::Isometry3d& pose, const EstimatorThresholds& thresholds,
                                const RotationTests& tests);

// Least-squares motion of the valid `members` between two marker fields
// (robust with `robust_mm` > 0; translation only when asked).
RigidFit fitConsecutive(const std::vector<int>& members, const MarkerField& before, const MarkerField& now,
                        double robust_mm, bool translation_only = false);

// The markers that moved as one rigid body between two marker fields (say a
// window apart): the least-squares fit over the valid `members`, trimmed one
// point at a time of residuals above trim_mm (rigid_fit.hpp), then robust with
// scale_mm. `members` becomes the kept set. Over a window, a sticking marker's
// residual is measurement noise whatever the motion, a slipping one's grows
// with its slide, so the kept set is the markers that stuck all along.
// Not ok (and `members` empty) unless at least max(min_kept, 3) markers fit
// within trim_mm.
RigidFit fitConsensus(std::vector<int>& members, const MarkerField& before, const MarkerField& now, double scale_mm,
                      double trim_mm, size_t min_kept = 0);

}  // namespace onetip::pose
