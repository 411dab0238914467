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
//   else larger extent >= min_spread (a line)         -> a rotation about S.z;
//   else                                               -> a translation only.
// A fitted rotation smaller than rotation_significance times its noise
// sqrt(2) sigma / (extent sqrt(n)) is not applied (a real rotation keeps
// growing against the anchors until it is significant; noise does not).
#pragma once

#include <cstdint>
#include <vector>

#include "contact/contact_field.hpp"
#include "contact/stick_slip_classifier.hpp"
#include "core/marker_field.hpp"
#include "pose/adaptive_pose_options.hpp"
#include "pose/rigid_fit.hpp"

namespace onetip::pose {

struct AnchoredFit {
  RigidFit fit;
  bool rotation_supported = false;  // the kept set fixes a general rotation
};

// `ids` (stick markers) becomes the kept set.
AnchoredFit fitAnchored(const contact::StickSlipClassifier& classifier, const contact::ContactField& field,
                        std::vector<int>& ids, const MarkerField& now, const Eigen::Isometry3d& pose,
                        const EstimatorThresholds& thresholds, double rotation_significance);

// The same, for a contact whose cap (`cap`, per marker id:
// touching_markers.hpp's capMarkers; empty or all zero: fitAnchored as is)
// must carry the fit: when the trim drops most of the cap's markers among
// `ids` (more than half), the skin beside the touch carried the fit (in a
// press it dips by about half as much as the touch and outnumbers it, so the
// touch looks like the outlier), and the fit is redone over the cap's
// markers among `ids` alone, which fix what their spread fixes (a
// translation, for one or two). A cap marker trimmed alone is one beginning
// to move off the finger, as any other; the fit stands (refitting over the
// rest of a cap too thin to fix a turn froze a rolling finger, campaign
// seed 140).
AnchoredFit fitAnchoredOnTheCap(const contact::StickSlipClassifier& classifier, const contact::ContactField& field,
                                std::vector<int>& ids, const std::vector<std::uint8_t>& cap, const MarkerField& now,
                                const Eigen::Isometry3d& pose, const EstimatorThresholds& thresholds,
                                double rotation_significance);

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
