#include "api/conversions.hpp"

namespace onetip::api {
namespace {

EventType toPublic(input::EventType t) { return static_cast<EventType>(static_cast<std::uint8_t>(t)); }

FrameStatus toPublic(pipeline::FrameStatus s) {
  switch (s) {
    case pipeline::FrameStatus::ok: return FrameStatus::ok;
    case pipeline::FrameStatus::reference: return FrameStatus::reference;
    case pipeline::FrameStatus::skipped: return FrameStatus::skipped;
    case pipeline::FrameStatus::lost: break;
  }
  return FrameStatus::lost;
}

// The internal and public event enums must stay in step (their numeric values cross the C ABI too).
static_assert(static_cast<int>(input::EventType::contact_begin) == static_cast<int>(EventType::contact_begin) &&
              static_cast<int>(input::EventType::input) == static_cast<int>(EventType::input) &&
              static_cast<int>(input::EventType::state_changed) == static_cast<int>(EventType::state_changed) &&
              static_cast<int>(input::EventType::error) == static_cast<int>(EventType::error));

}  // namespace

double toClockSeconds(pipeline::SteadyClock::time_point t) noexcept {
  return std::chrono::duration<double>(t.time_since_epoch()).count();
}

Event toEvent(const pipeline::PipelineEvent& e) {
  Event out;
  out.type = toPublic(e.event.type);
  out.frame = e.frame;
  out.t = e.event.t;
  out.arrival_s = toClockSeconds(e.arrival);
  out.input = e.event.input;
  out.sd = e.event.sd;
  out.state = e.event.state;
  out.message = e.event.message;
  return out;
}

FrameResult toFrameResult(const pipeline::PipelineFrame& f) {
  const pipeline::FrameResult& r = f.result;
  const input::TrackerResult& p = r.pose;
  const contact::ContactField& field = p.field;
  FrameResult out;
  out.frame = f.frame;
  out.t = r.t;
  out.arrival_s = toClockSeconds(f.arrival);
  out.status = toPublic(r.status);
  out.message = r.message;
  out.contact = p.contact;
  out.state = p.contact ? p.state : ContactState::none;
  out.raw = p.raw;
  out.input = p.input;
  out.sd = p.sd;
  out.pressed = p.pressed;
  out.out_of_range = p.out_of_range;
  out.rows = r.markers.rows;
  out.cols = r.markers.cols;
  out.contact_regions = static_cast<int>(field.regions.size());
  out.max_normal_mm = field.max_normal_mm;
  out.markers.resize(static_cast<size_t>(r.markers.size()));
  const bool has_field = static_cast<int>(field.valid.size()) == r.markers.size();
  for (size_t id = 0; id < out.markers.size(); ++id) {
    MarkerState& m = out.markers[id];
    m.valid = r.markers.valid[id] != 0;
    if (m.valid) {
      const auto& x = r.markers.position[id];
      m.x = x.x(), m.y = x.y(), m.z = x.z();
    }
    if (has_field && field.valid[id]) {
      const auto& u = field.displacement[id];
      m.displaced = true;
      m.ux = u.x(), m.uy = u.y(), m.uz = u.z();
      m.region = field.region_of.size() == out.markers.size() ? field.region_of[id] : -1;
    }
    if (p.step.stick_probability.size() == out.markers.size()) m.stick_probability = p.step.stick_probability[id];
  }
  out.times = {f.capture_ms,         f.queue_ms,        r.times.detect, r.times.track,
               r.times.triangulate,  r.times.contact,   r.times.pose,   r.times.process};
  return out;
}

SensorStats toSensorStats(const pipeline::PipelineStats& s) {
  SensorStats out;
  out.frames_captured = s.frames_captured;
  out.frames_processed = s.frames_processed;
  out.frames_dropped = s.frames_dropped;
  out.frames_skipped = s.frames_skipped;
  out.frames_lost = s.frames_lost;
  out.source_errors = s.source_errors;
  out.events_emitted = s.events_emitted;
  out.events_dropped = s.events_dropped;
  out.frame_results_dropped = s.frame_results_dropped;
  out.callback_errors = s.callback_errors;
  out.source_abandoned = s.source_abandoned;
  for (const pipeline::StageSummary& st : s.stages)
    out.stages.push_back({st.stage, st.count, st.median_ms, st.p99_ms, st.max_ms});
  return out;
}

}  // namespace onetip::api
