// contact/contact_analyzer.hpp — contact detection, contact regions and normals.
//
// Input: the current and the rest MarkerField, both in the sensor frame S (mm),
// on the same grid. Output: a ContactField (see contact_field.hpp for the maths):
// in contact while max |u_i| > contact_threshold_mm (paper: 0.1 mm); region =
// markers with |u_i| >= region_fraction * max |u_i.z| (paper: 50%), split into
// 8-connected components on the grid and each component at the valleys
// between two fingers' peaks; with several fingers, each finger's region is
// cut at region_fraction of its own peak (finger_valleys.hpp); regions smaller than
// min_region_markers are treated as noise and dropped. The default, 1, keeps
// the contact rule exact: the pad is in contact whenever its largest
// deformation exceeds the threshold, also while a fingertip between markers
// of a coarse pattern has pushed only the nearest one past the region cut
// (with 2, a 4.5 mm sphere on the 11 x 11 pattern went 0.44 mm deep before the
// contact began, and dz kept that offset: the truth starts at the threshold).
// Confidence: a marker of `now` whose confidence is below min_confidence is
// treated as not measured for the frame (ContactField::valid = 0). The
// default 0.2 follows the grid tracker's own tolerance (vision/grid_tracker.hpp:
// confidence = (1 - residual / tolerance) x good-link fraction, tolerance
// 0.3 of a square): with every link good, a marker more than 0.8 x the
// tolerance (0.24 of a square) from where its neighbours' motion puts it;
// or one with half its links bad and more than 0.6 x the tolerance off.
// Producers that do not grade (confidence 1) are unaffected.
// trustedMarkers(now, field): `now` with its markers graded below the field's
// min_confidence made invalid, so the stages after contact (stick/slip, pose)
// treat them as not measured too (remembered, not forgotten).
#pragma once

#include <cstdint>

#include "contact/contact_field.hpp"
#include "core/marker_field.hpp"

namespace onetip::contact {

// The deformation measure compared with the region cut:
//   modulus: |u_i| (the paper's rule, used with region_fraction 0.5);
//   normal:  -u_i.z, the normal deformation (the default, with 0.4). Against
//   the simulator's true contact the modulus rule grows the region behind a
//   sliding finger (tangential displacement counts), region IoU 0.77 on
//   slide_x; the normal rule at 40% gives 0.89 there and 0.94 for a press.
enum class RegionMeasure : std::uint8_t { normal = 0, modulus };

struct ContactAnalyzerOptions {
  double contact_threshold_mm = 0.1;  // on the largest deformation modulus
  RegionMeasure region_measure = RegionMeasure::normal;
  double region_fraction = 0.4;       // of the largest normal deformation
  int min_region_markers = 1;         // [1, ...] smaller components are noise
  double valley_prominence = 0.3;     // [0, 1] a second peak is another finger when the valley towards a deeper
                                      // one is this fraction of its depth below it (finger_valleys.hpp: between a
                                      // lone finger's <= 0.01 and two fingers' 0.41-0.60); 1: never split
  int min_valid_markers = 9;          // fewer valid pairs: status too_few_markers
  double min_confidence = 0.2;        // a marker graded below this is not measured (0: use every marker)
  void validate() const;              // throws InputError naming the bad field
};

class ContactAnalyzer {
 public:
  explicit ContactAnalyzer(ContactAnalyzerOptions options = {});
  // Throws InputError when the two fields are not on the same grid.
  ContactField analyze(const MarkerField& now_S, const MarkerField& rest_S) const;
  const ContactAnalyzerOptions& options() const { return options_; }

 private:
  ContactAnalyzerOptions options_;
};

// `now` without the markers `field` graded below its min_confidence (see above).
MarkerField trustedMarkers(const MarkerField& now, const ContactField& field);

}  // namespace onetip::contact
