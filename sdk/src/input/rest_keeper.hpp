// input/rest_keeper.hpp — keeps the rest reference true while nothing
// touches: a camera or mirror that shifts against the pad, a rest state that
// drifts with temperature, markers hidden for good.
//
// Out of contact every marker should sit on its rest position up to the
// measured noise sigma (pose/sensor_self_model.hpp). A camera or mirror that
// translates a view is corrected in the images before triangulation
// (vision/view_shift.hpp); what reaches S here is what that leaves: the pad
// moved in its housing, a camera that turned, slow drift. Each frame whose
// predecessor was out of contact, with e_i = p_i - r_i (S, mm) over the
// markers valid in both:
//  - a shift of the whole field: the rigid motion G = argmin sum w_i
//    |G r_i - p_i|^2 (Kabsch, Cauchy-reweighted at scale sigma_fit =
//    contact threshold / 4, pose/rigid_fit.hpp). A finger is local: it
//    leaves markers far from it where they were, so G stays near the
//    identity and its residual holds the dimple. A moved camera is global:
//    G carries every marker close to where it is (a shifted principal point
//    is not exactly a rigid motion in S: a 3 px step reads as 0.1 mm and
//    0.3 deg with 0.02 mm left over). When some marker moved by more than
//    move_sigmas sigma, G is taken for a move of the sensor if it moves some
//    marker by more than that itself (a finger's G stays near the identity
//    and leaves the rest alone), explains
//    every marker to within half the contact threshold (what is left then
//    never reads as a touch) and does not move the field's centre along S.z
//    by more than move_sigmas sigma (a flat plate pressed over the whole
//    pattern moves every marker rigidly into the pad). The rest becomes
//    G r and, when the largest displacement reaches move_report_mm, the
//    caller is told (an event). The contact analysis then sees only what a finger did.
//  - slow drift: each marker with |e_i| below drift_sigmas sigma moves its
//    rest towards p_i by dt / drift_time_s of e_i (an exponential average
//    with that time constant). Noise moves it by sigma sqrt(dt / 2 tau), a
//    finger entering cannot drag it beyond drift_sigmas sigma before the
//    contact threshold is met, and a drift slower than drift_sigmas sigma per
//    drift_time_s is followed.
// Markers valid at rest and missing for hidden_s seconds in a row are
// reported once as hidden (a torn or dirty gel); they keep their ids and
// rejoin when seen again. Markers the rest state itself lacks (a pad damaged
// before the sensor started) are reported with the first frame after it.
// A new reference from the caller (the pipeline's first frame or
// Sensor::reReference()) replaces the kept rest.
#pragma once

#include <string>
#include <vector>

#include "core/marker_field.hpp"

namespace onetip::input {

struct RestKeeperOptions {
  double move_sigmas = 8;      // [3, 1000] noise sigmas: a shift of the whole field, and what it must explain
  double move_report_mm = 0.02;  // [0, 10] mm: a sensor move at least this large is reported
  double drift_sigmas = 5;     // [1, 100] noise sigmas: markers closer than this to rest follow slow drift
  double drift_time_s = 10;    // [0.1, 3600] s: time constant of that drift following
  double hidden_s = 2;         // [0.1, 3600] s: missing this long, a marker is reported hidden
  void validate() const;       // throws InputError naming the bad field
};

struct RestUpdate {
  bool moved = false;          // the whole field shifted this frame and the rest followed it
  double moved_mm = 0;         // the largest marker displacement of that shift (mm)
  std::vector<int> hidden;     // markers newly reported hidden this frame (ids)
};

class RestKeeper {
 public:
  explicit RestKeeper(RestKeeperOptions options = {});
  // `reference` the caller's rest field (S, mm), `now` this frame's; `was_in_contact` the last frame's
  // contact; noise_mm and contact_threshold_mm from what the sensor measures and the contact stage;
  // t in seconds. Returns what changed; rest() is the rest to analyse `now` against.
  RestUpdate update(const MarkerField& now, const MarkerField& reference, bool was_in_contact, double noise_mm,
                    double contact_threshold_mm, double t);
  const MarkerField& rest() const { return rest_; }
  void reset();

 private:
  bool alignWholeField(const MarkerField& now, double noise_mm, double contact_threshold_mm, RestUpdate& out);
  void followDrift(const MarkerField& now, double noise_mm, double dt);
  void trackHidden(const MarkerField& now, double t, RestUpdate& out);

  RestKeeperOptions options_;
  MarkerField reference_, rest_;
  bool have_t_ = false;
  double last_t_ = 0;
  std::vector<double> missing_since_;  // per marker: when it was last seen (t), or -1 while seen
  std::vector<std::uint8_t> reported_;
};

// One line naming the hidden markers, for an event.
std::string describeHidden(const std::vector<int>& ids);

}  // namespace onetip::input
