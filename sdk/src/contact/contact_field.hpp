// contact/contact_field.hpp — the result of contact analysis for one frame.
//
// Per marker id (row * cols + col) of a MarkerField in the sensor frame S:
//   u_i = now_i - rest_i (mm), valid where both positions are valid;
//   normal deformation n_i = -u_i.z (mm, positive when pressed into the pad);
//   the outward surface normal of the deformed marker layer (unit, S, pointing
//   out of the pad towards the finger), from grid neighbours.
// A marker measured with a confidence (MarkerField::confidence, 0..1) below
// the analyzer's min_confidence is treated as not measured for the frame:
// invalid here, so no region, centroid or pose fit uses it (trustedMarkers
// gives the stages after contact the same view of `now`).
// Contact (the paper's Sec. III-C rule): in contact while max_i |u_i| exceeds
// the contact threshold; the contact region holds the markers whose
// deformation (normal -u_i.z by default, or the paper's modulus |u_i|) is at
// least region_fraction * max_i |u_i.z|. With several fingers (peaks of the
// normal deformation apart by a valley, contact/finger_valleys.hpp) each
// finger's region is cut at region_fraction of its own peak. Regions are
// 8-connected on the marker grid, largest first.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace onetip::contact {

enum class ContactFieldStatus : std::uint8_t {
  ok = 0,           // analysed (in contact or not)
  too_few_markers,  // fewer valid marker pairs than the options require: no decision
};

struct ContactRegion {
  std::vector<int> markers;             // marker ids, ascending
  Eigen::Vector3d rest_centroid{0, 0, 0};   // mean rest position of the members (S, mm)
  Eigen::Vector3d footprint_centre{0, 0, 0};  // apex of the normal-deformation cap (footprint_centre.hpp; S, mm)
  double peak_normal_mm = 0;            // largest normal deformation in the region
  double cut_mm = 0;                    // its finger's cut: region_fraction x that finger's peak |u_i.z| (mm)
};

struct ContactField {
  ContactFieldStatus status = ContactFieldStatus::ok;
  bool in_contact = false;
  double max_modulus_mm = 0;            // max |u_i|
  double max_normal_mm = 0;             // max |u_i.z|
  double region_cut_mm = 0;             // region_fraction * max_normal_mm (the deepest finger's cut)
  int valid_markers = 0;                // markers valid in both now and rest (and confident enough)
  int low_confidence = 0;               // markers measured in now but graded below min_confidence
  std::vector<Eigen::Vector3d> displacement;  // u_i (zero where invalid)
  std::vector<std::uint8_t> valid;            // now and rest both valid, confidence >= min_confidence
  std::vector<float> confidence;              // now's confidence where now is valid, 0 elsewhere
  double min_confidence = 0;            // the analyzer's cut: now-valid markers below it are not measured
  std::vector<Eigen::Vector3d> normal;        // deformed surface normal (S)
  std::vector<std::uint8_t> normal_valid;
  std::vector<int> region_of;           // index into regions, -1 outside every region
  std::vector<ContactRegion> regions;   // largest first; empty when not in contact

  bool inRegion(int id) const { return region_of[static_cast<size_t>(id)] >= 0; }
  // The cut of the region holding the first of `members` (region_cut_mm when it is in none).
  double cutOf(const std::vector<int>& members) const {
    const int r = members.empty() ? -1 : region_of[static_cast<size_t>(members.front())];
    return r >= 0 ? regions[static_cast<size_t>(r)].cut_mm : region_cut_mm;
  }
};

}  // namespace onetip::contact
