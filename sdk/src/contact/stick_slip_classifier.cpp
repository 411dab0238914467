#include "contact/stick_slip_classifier.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.hpp"

namespace onetip::contact {

void StickSlipOptions::validate() const {
  if (!(slip_threshold_mm > 0) || !std::isfinite(slip_threshold_mm))
    throw InputError("stick/slip options: slip_threshold_mm must be a positive number");
  if (stick_hold_frames < 1) throw InputError("stick/slip options: stick_hold_frames must be at least 1");
}

StickSlipClassifier::StickSlipClassifier(StickSlipOptions options) : options_(options) { options_.validate(); }

void StickSlipClassifier::setOptions(const StickSlipOptions& options) {
  options.validate();
  options_ = options;
}

void StickSlipClassifier::reset(int marker_count) {
  label_.assign(static_cast<size_t>(marker_count), MarkerLabel::outside);
  unseen_label_.assign(static_cast<size_t>(marker_count), MarkerLabel::outside);
  anchor_.assign(static_cast<size_t>(marker_count), Eigen::Vector3d::Zero());
  quiet_frames_.assign(static_cast<size_t>(marker_count), 0);
  frames_in_contact_.assign(static_cast<size_t>(marker_count), 0);
  drift_.assign(static_cast<size_t>(marker_count), 0.0);
}

void StickSlipClassifier::retain(const std::vector<int>& members, const MarkerField& now) {
  std::vector<std::uint8_t> keep(label_.size(), 0);
  for (int id : members)
    if (now.valid[static_cast<size_t>(id)]) keep[static_cast<size_t>(id)] = 1;
  for (size_t i = 0; i < label_.size(); ++i) {
    if (keep[i]) continue;
    if (now.valid[i]) unseen_label_[i] = MarkerLabel::outside;          // measured outside: forgotten
    else if (label_[i] != MarkerLabel::outside) unseen_label_[i] = label_[i];  // not measured: remembered
    label_[i] = MarkerLabel::outside;
  }
}

void StickSlipClassifier::reanchor(int id, const MarkerField& now, const Eigen::Isometry3d& pose_inverse) {
  const Eigen::Vector3d anchor = pose_inverse * now.position[static_cast<size_t>(id)];
  drift_[static_cast<size_t>(id)] = (anchor - anchor_[static_cast<size_t>(id)]).norm();  // rigid: same as in S
  anchor_[static_cast<size_t>(id)] = anchor;
  quiet_frames_[static_cast<size_t>(id)] = 0;
}

void StickSlipClassifier::anchorNew(const std::vector<int>& members, const MarkerField& now,
                                    const Eigen::Isometry3d& pose) {
  const Eigen::Isometry3d inv = pose.inverse();
  for (int id : members) {
    const size_t i = static_cast<size_t>(id);
    if (!now.valid[i] || label_[i] != MarkerLabel::outside) continue;
    if (unseen_label_[i] != MarkerLabel::outside) {  // back after frames unmeasured: judged on its old anchor
      label_[i] = std::exchange(unseen_label_[i], MarkerLabel::outside);
      continue;
    }
    label_[i] = MarkerLabel::stick;
    frames_in_contact_[i] = 0;
    reanchor(id, now, inv);
    drift_[i] = 0;
  }
}

int StickSlipClassifier::classify(const MarkerField& now, const std::vector<Eigen::Vector3d>& normals,
                                  const Eigen::Isometry3d& pose) {
  const Eigen::Isometry3d inv = pose.inverse();
  int changed = 0;
  for (size_t i = 0; i < label_.size(); ++i) {
    if (label_[i] == MarkerLabel::outside) continue;
    ++frames_in_contact_[i];
    const Eigen::Vector3d d = now.position[i] - pose * anchor_[i];
    drift_[i] = d.norm();
    const Eigen::Vector3d& n = normals[i];
    const double normal_part = std::abs(d.dot(n));
    const double tangential_part = (d - d.dot(n) * n).norm();
    const int id = static_cast<int>(i);
    if (d.norm() > options_.slip_threshold_mm) {
      const MarkerLabel next = tangential_part >= normal_part ? MarkerLabel::slip : MarkerLabel::detached;
      changed += label_[i] == next ? 0 : 1;
      label_[i] = next;
      reanchor(id, now, inv);
    } else if (label_[i] != MarkerLabel::stick && ++quiet_frames_[i] >= options_.stick_hold_frames) {
      label_[i] = MarkerLabel::stick;
      ++changed;
    }
  }
  return changed;
}

void StickSlipClassifier::markAllSlipping(const MarkerField& now, const Eigen::Isometry3d& pose) {
  const Eigen::Isometry3d inv = pose.inverse();
  for (size_t i = 0; i < label_.size(); ++i)
    if (label_[i] != MarkerLabel::outside) {
      label_[i] = MarkerLabel::slip;
      reanchor(static_cast<int>(i), now, inv);
    }
}

void StickSlipClassifier::markAllSticking(const MarkerField& now, const Eigen::Isometry3d& pose) {
  const Eigen::Isometry3d inv = pose.inverse();
  for (size_t i = 0; i < label_.size(); ++i)
    if (label_[i] != MarkerLabel::outside) {
      label_[i] = MarkerLabel::stick;
      reanchor(static_cast<int>(i), now, inv);
    }
}

void StickSlipClassifier::reattach(const std::vector<int>& ids, const MarkerField& at, const Eigen::Isometry3d& pose) {
  const Eigen::Isometry3d inv = pose.inverse();
  for (int id : ids)
    if (label_[static_cast<size_t>(id)] != MarkerLabel::outside) {
      label_[static_cast<size_t>(id)] = MarkerLabel::stick;
      reanchor(id, at, inv);
    }
}

void StickSlipClassifier::markSticking(const std::vector<int>& sticking, const MarkerField& now,
                                       const Eigen::Isometry3d& pose) {
  markAllSlipping(now, pose);
  for (int id : sticking)
    if (label_[static_cast<size_t>(id)] != MarkerLabel::outside) label_[static_cast<size_t>(id)] = MarkerLabel::stick;
}

std::vector<int> StickSlipClassifier::withLabel(MarkerLabel l) const {
  std::vector<int> ids;
  for (size_t i = 0; i < label_.size(); ++i)
    if (label_[i] == l) ids.push_back(static_cast<int>(i));
  return ids;
}

}  // namespace onetip::contact
