#include "pose/model_selection.hpp"

#include "pose/stick_slip_solver.hpp"

namespace onetip::pose {

std::string_view toString(PoseModel m) noexcept {
  switch (m) {
    case PoseModel::kabsch: return "kabsch";
    case PoseModel::stick_slip: return "stick_slip";
    case PoseModel::centroid: return "centroid";
    case PoseModel::none: break;
  }
  return "none";
}

PoseModel selectModel(const ModelEvidence& e, ModelPolicy policy) {
  if (policy == ModelPolicy::centroid_only) return PoseModel::centroid;
  if (policy == ModelPolicy::kabsch_only) return PoseModel::kabsch;
  if (!e.stick_fit_ok || !stickSlipSolvable(e.n_stick, e.n_slip) || e.stick_set_creeps) return PoseModel::centroid;
  const bool full_stick = e.n_slip == 0 && policy == ModelPolicy::adaptive;
  if (full_stick || !(e.rotation_supported || e.slip_fixes_rotation)) return PoseModel::kabsch;
  return PoseModel::stick_slip;
}

bool thinStickSetTrusted(int n_stick, bool small_contact, bool settled, int min_thin_stick_markers) {
  return n_stick >= min_thin_stick_markers || (small_contact && settled);
}

}  // namespace onetip::pose
