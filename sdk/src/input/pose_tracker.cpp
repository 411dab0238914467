#include "input/pose_tracker.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "core/option_checks.hpp"

namespace onetip::input {

void PoseTrackerOptions::validate() const {
  contact.validate();
  pose.validate();
  filter.validate();
  shaping.validate();
  press.validate();
  rest.validate();
  recovery.validate();
  creep.validate();
  onset.validate();
  for (double r : working_range) requireAbove("pose tracker: working_range entries", r, 0);
  requireAtLeast("pose tracker: clamp_factor", clamp_factor, 1);
  requireInRange("pose tracker: marker_depth_mm", marker_depth_mm, 0, MarkerPattern::kMaxMarkerDepthMm, "mm");
}

PoseTracker::PoseTracker(PoseTrackerOptions options)
    : options_((options.validate(), options)),
      analyzer_(options_.contact),
      self_(options_.pose.self),
      rest_keeper_(options_.rest),
      recovery_(options_.recovery),
      creep_(options_.creep),
      onset_band_(options_.onset),
      estimator_(options_.pose),
      filter_(makeInputFilter(options_.filter)),
      button_(options_.press) {}

void PoseTracker::reset() {
  estimator_.reset();
  if (filter_) filter_->reset();
  button_.reset();
  rest_keeper_.reset();
  recovery_.reset();
  creep_.reset();
  onset_band_.reset();
  last_ = TrackerResult{};
}

void PoseTracker::emit(TrackerResult& r, EventType type, std::string message) const {
  r.events.push_back({type, r.t, r.input, r.sd, r.state, std::move(message)});
}

void PoseTracker::fillOutputs(TrackerResult& r) {
  r.composed = accumulator_.composed();
  r.euler_sum = accumulator_.eulerSum();
  auto v = accumulator_.value(options_.accumulation).asArray();
  for (size_t k = 0; k < 6; ++k) {
    const double range = options_.working_range[k];
    // dz is a press depth, [0, range]; pulling out of the pad shows only as noise.
    const double low = k == 2 ? -(options_.clamp_factor - 1) * range : -range;
    r.out_of_range = r.out_of_range || v[k] > range || v[k] < low;
    const double limit = options_.clamp_factor * range;
    v[k] = std::clamp(v[k], -limit, limit);
  }
  r.raw = Input6::fromArray(v);
  r.sd = r.step.sd;
  const Input6 smooth = filter_ ? filter_->apply(r.raw, r.t) : r.raw;
  r.input = options_.shaping.apply(smooth);
}

TrackerResult PoseTracker::update(const MarkerField& now_S, const MarkerField& rest_S, double t) {
  TrackerResult r;
  r.t = t;
  const auto contact_start = std::chrono::steady_clock::now();
  const RestUpdate rest_update = rest_keeper_.update(now_S, rest_S, last_.contact, self_.current().noise_mm,
                                                     options_.contact.contact_threshold_mm, t);
  // The gel's measured creep, and a finger on a recovering gel: the markers as the finger alone moves them
  // (gel_creep.hpp, gel_recovery.hpp).
  const MarkerField unloaded = withoutRemainder(now_S, creep_.advance(now_S, rest_keeper_.rest(), t));
  MarkerField now = withoutRemainder(unloaded, recovery_.advance());
  r.field = analyzer_.analyze(now, rest_keeper_.rest());
  const bool recovering =
      r.field.status == contact::ContactFieldStatus::ok &&
      recovery_.recovering(r.field, last_.contact, self_.current().largest_axis_noise_mm,
                           options_.contact.contact_threshold_mm);
  if (recovering) clearContact(r.field);
  if (recovery_.remainderBegan()) {
    now = withoutRemainder(unloaded, recovery_.remainder());
    r.field = analyzer_.analyze(now, rest_keeper_.rest());
  }
  r.contact_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - contact_start).count();
  if (r.field.status == contact::ContactFieldStatus::too_few_markers) {
    TrackerResult held = last_;
    held.t = t;
    held.held = true;
    held.field = std::move(r.field);
    held.contact_ms = r.contact_ms;
    held.events.clear();
    emit(held, EventType::error,
         "too few valid markers (" + std::to_string(held.field.valid_markers) + "): output held");
    return held;
  }
  // A field sinking through the threshold (a creeping gel after a lift-off) begins no contact from noise.
  const bool may_begin = onset_band_.mayBegin(r.field.max_modulus_mm, r.field.valid_markers,
                                              self_.current().largest_axis_noise_mm,
                                              options_.contact.contact_threshold_mm);
  const auto holdBackNoise = [&] {
    if (!last_.contact && r.field.in_contact && !may_begin) clearContact(r.field);
  };
  holdBackNoise();
  // This frame measured the gel (a held press, a recovery, or the decay since the finger's field left): it is
  // analysed again without the gel's delayed part, so a contact ends in the frame its finger is found gone.
  const bool gel_measured = creep_.observe(now, rest_keeper_.rest(), t, r.field.in_contact,
                                           self_.current().largest_axis_noise_mm, recovery_.remainder(),
                                           recovery_.decayingFrames());
  if (gel_measured) {
    recovery_.reset();  // the measured creep holds what was left of a recovery
    now = withoutRemainder(now_S, creep_.delayed());
    r.field = analyzer_.analyze(now, rest_keeper_.rest());
    holdBackNoise();
  }
  self_.setRest(rest_S);
  self_.observe(unloaded, t, !r.field.in_contact && !recovering);  // a recovering gel moves: not noise
  r.step = estimator_.update(r.field, now, self_.current());
  r.contact = r.step.active;
  r.state = r.step.state;
  if (r.step.onset) {
    accumulator_.reset(r.step.onset_centroid, options_.marker_depth_mm);
    if (filter_) filter_->reset();
  } else if (r.step.active) {
    accumulator_.add(r.step.increment);
  }
  if (r.contact) fillOutputs(r);

  // A contact ends when the pad is released, or when its finger lifts while
  // another stays (the estimator then begins a new contact in the same frame).
  if (last_.contact && (!r.contact || r.step.onset)) {
    if (button_.pressed()) {
      button_.reset();
      emit(r, EventType::release);
    }
    if (filter_ && !r.contact) filter_->reset();
    emit(r, EventType::contact_end);
  }
  if (r.step.onset) emit(r, EventType::contact_begin);
  if (r.state != last_.state) emit(r, EventType::state_changed);
  if (r.contact) {
    emit(r, EventType::input);
    if (button_.update(r.raw.dz)) emit(r, button_.pressed() ? EventType::press : EventType::release);
    if (r.step.solver_failed) emit(r, EventType::error, "pose solver failed: footprint centroid used");
    if (r.step.step_limited) emit(r, EventType::error, "motion step limited to the configured maximum");
    if (r.out_of_range && !last_.out_of_range) emit(r, EventType::error, "beyond the working range");
  }
  if (rest_update.moved)
    emit(r, EventType::error,
         "the camera moved against the pad by " + std::to_string(rest_update.moved_mm) +
             " mm: the rest reference follows it");
  if (!rest_update.hidden.empty()) emit(r, EventType::error, describeHidden(rest_update.hidden));
  if (gel_measured) emit(r, EventType::error, creep_.model().describe());
  r.pressed = button_.pressed();
  last_ = r;
  last_.field = contact::ContactField{};  // only the outputs are needed to hold a frame
  return r;
}

}  // namespace onetip::input
