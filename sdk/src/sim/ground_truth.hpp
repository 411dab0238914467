// sim/ground_truth.hpp — the simulator's exact answer for every frame.
//
// The 6-D ground truth follows docs/reference.md using the SDK's own contact rule
// applied to the exact marker field, so that a perfect measurement reproduces
// it: the pad is "in contact" while the largest marker deformation modulus
// exceeds contact_threshold_mm (0.1 mm); at onset T_onset is the finger's pose
// (the followed indenter, below) and c0 the centroid of the rest positions of the markers whose
// deformation modulus is at least region_fraction (50%) of the largest normal
// deformation. Then T = T_now * inverse(T_onset) and [dx..roll] per
// core/rotation.hpp. The state column comes from the contact model's nodes
// (no slip: stick; all slip: slip; otherwise partial_slip).
// Several fingers (the SDK tracks one contact at a time, largest first): the
// finger followed is the indenter touching the most pad nodes at onset; when
// it touches none while the pad is still in contact (it lifted, another
// finger stays), its contact has ended and a new one begins on the indenter
// touching the most nodes then (T_onset and c0 taken again). With one
// indenter this never happens: a pad no indenter touches is at rest.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "core/marker_field.hpp"
#include "onetip/types.hpp"

namespace onetip::sim {

struct GroundTruthFrame {
  int index = 0;
  double t = 0;
  MarkerField markers;                  // S, mm (all markers valid)
  std::vector<std::uint8_t> contact;    // per marker: its node touches an indenter
  std::vector<std::uint8_t> slip;       // per marker: its node slips
  std::vector<int> owner;               // per marker: the indenter its node touches (-1: none)
  bool in_contact = false;              // by the SDK's threshold rule
  ContactState state = ContactState::none;
  Input6 input;                         // zero when not in contact
  Eigen::Vector3d onset_centroid{0, 0, 0};  // c0 of `input` (S, mm); zero when not in contact
  std::vector<Eigen::Isometry3d> indenter_poses;  // S
  std::vector<int> indenter_nodes;      // per indenter: pad nodes it touches
  int followed = 0;                     // the indenter whose motion `input` is (see above)
};

class GroundTruthPose {
 public:
  explicit GroundTruthPose(double contact_threshold_mm = 0.1, double region_fraction = 0.5)
      : threshold_(contact_threshold_mm), fraction_(region_fraction) {}
  // Fills frame.in_contact, frame.followed and frame.input from
  // frame.markers (S), the rest markers (S), frame.indenter_nodes and the
  // followed indenter's pose (S).
  void update(GroundTruthFrame& frame, const MarkerField& rest) { update(frame, rest, frame.markers); }
  // The same with the rule applied to `deformed` (S) instead of frame.markers.
  void update(GroundTruthFrame& frame, const MarkerField& rest, const MarkerField& deformed);

 private:
  double threshold_, fraction_;
  bool active_ = false;
  int followed_ = 0;
  Eigen::Isometry3d onset_pose_ = Eigen::Isometry3d::Identity();
  Eigen::Vector3d c0_ = Eigen::Vector3d::Zero();
};

}  // namespace onetip::sim
