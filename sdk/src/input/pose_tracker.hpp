// input/pose_tracker.hpp — the facade: marker fields in, 6-D input and events out.
//
// Per frame: update(now_S, rest_S, t) with the current and rest MarkerField in
// the sensor frame S (mm, same grid) and the time in seconds runs
//   the rest kept true while nothing touches (rest_keeper.hpp: a shifted
//   camera, slow drift, hidden markers; each reported as an error event)
//   -> contact analysis (contact/contact_analyzer.hpp), without the gel's
//      creep once it is measured (gel_creep.hpp) and without the
//      deformation of a gel recovering after the finger left (gel_recovery.hpp)
//   -> no contact begins from noise while a field that sank through the
//      contact threshold is still within the noise of it (onset_band.hpp)
//   -> the gel measured from this frame (a held press, a recovery, or the
//      decay since the finger's field left): analysed again without its creep
//   -> what the sensor measures about itself (pose/sensor_self_model.hpp:
//      marker noise on the frames out of contact, pitch, frame interval)
//   -> stick/slip labels and the finger's increment (pose/adaptive_pose_estimator.hpp)
//   -> the 6-D signal since contact onset (pose_accumulator.hpp; re-zeroed at
//      every new contact; both accumulations are reported, `raw` is the chosen one)
//   -> limited to clamp_factor x the working range (so it stays bounded),
//   -> optional filter and per-axis gain / dead zone (`input`, for applications)
//   -> events (input_event.hpp).
// `raw` is the measurement (what accuracy is judged on, and what pose.csv
// holds); `input` adds the interaction shaping. Angles in degrees.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "contact/contact_analyzer.hpp"
#include "core/pattern.hpp"
#include "input/input_event.hpp"
#include "input/input_filter.hpp"
#include "input/gel_creep.hpp"
#include "input/gel_recovery.hpp"
#include "input/input_shaping.hpp"
#include "input/onset_band.hpp"
#include "input/pose_accumulator.hpp"
#include "input/press_button.hpp"
#include "input/rest_keeper.hpp"
#include "pose/adaptive_pose_estimator.hpp"
#include "pose/sensor_self_model.hpp"

namespace onetip::input {

struct PoseTrackerOptions {
  contact::ContactAnalyzerOptions contact;
  pose::AdaptivePoseOptions pose;
  Accumulation accumulation = Accumulation::composed;
  InputFilterOptions filter;
  InputShaping shaping;
  PressButtonOptions press;
  RestKeeperOptions rest;
  GelRecoveryOptions recovery;
  GelCreepOptions creep;
  OnsetBandOptions onset;
  // The paper's working range (Eq. 18): |dx|, |dy| <= 4 mm, dz <= 3 mm,
  // |yaw| <= 15 deg, |pitch|, |roll| <= 40 deg. Beyond it the result says
  // out_of_range; `raw` is clamped to clamp_factor times it.
  std::array<double, 6> working_range{4, 4, 3, 15, 40, 40};
  double clamp_factor = 1.5;
  // How deep the markers lie below the contact surface (core/pattern.hpp; the
  // pipeline takes it from the pattern), [0, MarkerPattern::kMaxMarkerDepthMm] mm: the 6-D signal is the
  // finger's motion, the markers' conjugated by it (pose_accumulator.hpp).
  double marker_depth_mm = MarkerPattern{}.marker_depth_mm;
  void validate() const;  // throws InputError naming the bad field
};

struct TrackerResult {
  double t = 0;
  bool contact = false;
  ContactState state = ContactState::none;
  Input6 raw;              // chosen accumulation, clamped; zero out of contact
  Input6 input;            // raw, filtered and shaped
  Input6 sd;               // one standard deviation of each component of raw (mm, deg; pose/pose_uncertainty.hpp)
  Input6 composed;         // SE(3) composition (unclamped)
  Input6 euler_sum;        // the paper's Euler-increment sum (unclamped)
  bool out_of_range = false;
  bool pressed = false;
  bool held = false;       // no decision this frame (too few markers): previous output repeated
  pose::PoseStep step;
  contact::ContactField field;
  std::vector<InputEvent> events;
  double contact_ms = 0;   // time spent in contact analysis this frame (the rest is the pose solve)
};

class PoseTracker {
 public:
  explicit PoseTracker(PoseTrackerOptions options = {});
  // Throws InputError when now_S and rest_S are not on the same grid.
  TrackerResult update(const MarkerField& now_S, const MarkerField& rest_S, double t);
  void reset();
  const PoseTrackerOptions& options() const { return options_; }
  const pose::SensorSelf& sensorSelf() const { return self_.current(); }
  const CreepModel& gelCreep() const { return creep_.model(); }  // the gel's creep, once measured

 private:
  void emit(TrackerResult& r, EventType type, std::string message = {}) const;
  void fillOutputs(TrackerResult& r);

  PoseTrackerOptions options_;
  contact::ContactAnalyzer analyzer_;
  pose::SensorSelfModel self_;
  RestKeeper rest_keeper_;
  GelRecovery recovery_;
  GelCreep creep_;
  OnsetBand onset_band_;
  pose::AdaptivePoseEstimator estimator_;
  PoseAccumulator accumulator_;
  std::unique_ptr<InputFilter> filter_;
  PressButton button_;
  TrackerResult last_;
};

}  // namespace onetip::input
