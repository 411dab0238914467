// pose/model_selection.hpp — which of the paper's three motion models a frame
// gets, from what the contact shows (paper Sec. III-D, Eq. 16).
//
// adaptive policy, in order:
//   no usable stick fit, or Eq. 16 fails
//     (3 n_stick + n_slip < 6 or n_stick = 0),
//     or the stick set creeps (stick_set_creeps)       -> centroid (footprint) model;
//   no slipping marker, or a stick set that cannot
//     fix a general rotation, even with the slip
//     markers' normal residuals (slip_fixes_rotation)  -> Kabsch (Eq. 1; what the set fixes);
//   otherwise (partial slip)                           -> Ceres stick/slip least squares (Eq. 13-15).
// stick_slip_only runs Ceres at full stick too (same fall-backs); kabsch_only
// and centroid_only give their model always.
#pragma once

#include <cstdint>
#include <string_view>

#include "pose/adaptive_pose_options.hpp"

namespace onetip::pose {

enum class PoseModel : std::uint8_t { none = 0, kabsch, stick_slip, centroid };
std::string_view toString(PoseModel m) noexcept;

struct ModelEvidence {
  bool stick_fit_ok = false;
  bool rotation_supported = false;   // the stick set alone fixes a general rotation
  int n_stick = 0, n_slip = 0;
  // A thin stick set (a line fixes no rotation about itself) of at least
  // min_thin_stick_markers, whose rotation the slip markers' normal residuals
  // fix (stickSlipRotationInformation >= min spread^2: some marker acts at
  // the min spread from every axis): Eq. 13-15 can give the whole rotation.
  bool slip_fixes_rotation = false;
  // On a developed contact, a thin stick set (no general rotation, fewer than
  // min_thin_stick_markers) that slipping markers overtake
  // (pose/stick_set_creep.hpp): the finger went further than it says, its
  // markers slip together, and Eq. 16 holds by the count alone.
  bool stick_set_creeps = false;
};

PoseModel selectModel(const ModelEvidence& evidence, ModelPolicy policy);

// Whether a thin stick set of n_stick markers may take Eq. 13-15 (the
// slip_fixes_rotation case above). With at least min_thin_stick_markers, yes.
// With fewer, only on a contact too small to declare macroscopic slip (where
// no slide test is there to be misled) and when each of its markers has been
// in the contact for the stick hold (`settled`): markers the contact has just
// reached lie at its edge, where the pressure is least and the skin creeps
// first (a slide's leading edge).
bool thinStickSetTrusted(int n_stick, bool small_contact, bool settled, int min_thin_stick_markers);

}  // namespace onetip::pose
