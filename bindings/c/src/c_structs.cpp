#include "c_structs.hpp"

#include <algorithm>
#include <cstring>
#include <new>

namespace onetip::c_api {
namespace {

void copyInput(double (&dst)[6], const Input6& v) noexcept {
  const std::array<double, 6> a = v.asArray();
  std::copy(a.begin(), a.end(), dst);
}

std::int32_t fill(onetip_error* error, onetip_error_kind kind, const std::string& message) noexcept {
  if (error) {
    error->kind = kind;
    copyString(error->message, sizeof error->message, message);
  }
  return kind;
}

}  // namespace

void copyString(char* dst, std::size_t size, const std::string& text) noexcept {
  if (size == 0) return;
  const std::size_t n = std::min(size - 1, text.size());
  std::memcpy(dst, text.data(), n);
  dst[n] = '\0';
}

void requireNonNull(const void* p, const char* what) {
  if (!p) throw CError(ONETIP_ERROR_NULL_ARGUMENT, std::string(what) + ": NULL");
}

void requireAbiVersion(std::uint32_t caller_version) {
  if (caller_version != ONETIP_C_ABI_VERSION)
    throw CError(ONETIP_ERROR_VERSION, "onetip C ABI version mismatch: the caller was built against version " +
                                           std::to_string(caller_version) + ", this library implements version " +
                                           std::to_string(ONETIP_C_ABI_VERSION) + " (rebuild against its onetip_c.h)");
}

std::int32_t reportOk(onetip_error* error) noexcept { return fill(error, ONETIP_OK, ""); }

std::int32_t reportCurrentException(onetip_error* error) noexcept {
  try {
    throw;
  } catch (const CError& e) {
    return fill(error, e.kind(), e.what());
  } catch (const Error& e) {
    switch (e.kind()) {
      case ErrorKind::input: return fill(error, ONETIP_ERROR_INPUT, e.what());
      case ErrorKind::state: return fill(error, ONETIP_ERROR_STATE, e.what());
      case ErrorKind::internal: break;
    }
    return fill(error, ONETIP_ERROR_INTERNAL, e.what());
  } catch (const std::bad_alloc&) {
    return fill(error, ONETIP_ERROR_INTERNAL, "out of memory");
  } catch (const std::exception& e) {
    return fill(error, ONETIP_ERROR_INTERNAL, std::string("internal error: ") + e.what());
  } catch (...) {
    return fill(error, ONETIP_ERROR_INTERNAL, "internal error: unknown exception");
  }
}

onetip_event toC(const Event& e) noexcept {
  onetip_event c{};
  c.type = static_cast<std::int32_t>(e.type);
  c.state = static_cast<std::int32_t>(e.state);
  c.frame = e.frame;
  c.t = e.t;
  c.arrival_s = e.arrival_s;
  copyInput(c.input, e.input);
  copyString(c.message, sizeof c.message, e.message);
  return c;
}

onetip_frame toC(const FrameResult& f) noexcept {
  onetip_frame c{};
  c.frame = f.frame;
  c.t = f.t;
  c.arrival_s = f.arrival_s;
  c.status = static_cast<std::int32_t>(f.status);
  c.contact = f.contact ? 1 : 0;
  c.state = static_cast<std::int32_t>(f.state);
  c.pressed = f.pressed ? 1 : 0;
  c.out_of_range = f.out_of_range ? 1 : 0;
  c.rows = f.rows;
  c.cols = f.cols;
  c.contact_regions = f.contact_regions;
  c.max_normal_mm = f.max_normal_mm;
  copyInput(c.raw, f.raw);
  copyInput(c.input, f.input);
  const StageTimes& t = f.times;
  const double times[ONETIP_FRAME_STAGES] = {t.capture,     t.queue,   t.detect, t.track,
                                             t.triangulate, t.contact, t.pose,   t.process};
  std::copy(std::begin(times), std::end(times), c.times_ms);
  copyString(c.message, sizeof c.message, f.message);
  return c;
}

std::vector<onetip_marker> markersToC(const FrameResult& f) {
  std::vector<onetip_marker> out(f.markers.size());
  for (std::size_t id = 0; id < out.size(); ++id) {
    const MarkerState& m = f.markers[id];
    onetip_marker& c = out[id];
    c.id = static_cast<std::int32_t>(id);
    c.valid = m.valid ? 1 : 0;
    c.displaced = m.displaced ? 1 : 0;
    c.region = m.region;
    c.position[0] = m.x, c.position[1] = m.y, c.position[2] = m.z;
    c.displacement[0] = m.ux, c.displacement[1] = m.uy, c.displacement[2] = m.uz;
  }
  return out;
}

onetip_event_sd toCWithSd(const Event& e) noexcept {
  onetip_event_sd c{};
  c.event = toC(e);
  copyInput(c.sd, e.sd);
  return c;
}

onetip_frame_sd toCWithSd(const FrameResult& f) noexcept {
  onetip_frame_sd c{};
  c.frame = toC(f);
  copyInput(c.sd, f.sd);
  return c;
}

std::vector<onetip_marker_sd> markersWithSdToC(const FrameResult& f) {
  const std::vector<onetip_marker> plain = markersToC(f);
  std::vector<onetip_marker_sd> out(plain.size());
  for (std::size_t id = 0; id < out.size(); ++id) {
    out[id].marker = plain[id];
    out[id].stick_probability = f.markers[id].stick_probability;
  }
  return out;
}

onetip_stats toC(const SensorStats& s) noexcept {
  onetip_stats c{};
  c.frames_captured = s.frames_captured;
  c.frames_processed = s.frames_processed;
  c.frames_dropped = s.frames_dropped;
  c.frames_skipped = s.frames_skipped;
  c.frames_lost = s.frames_lost;
  c.source_errors = s.source_errors;
  c.events_emitted = s.events_emitted;
  c.events_dropped = s.events_dropped;
  c.frame_results_dropped = s.frame_results_dropped;
  c.callback_errors = s.callback_errors;
  c.source_abandoned = s.source_abandoned ? 1 : 0;
  const std::size_t n = std::min<std::size_t>(s.stages.size(), ONETIP_MAX_STAGES);
  c.stage_count = static_cast<std::int32_t>(n);
  for (std::size_t i = 0; i < n; ++i) {
    copyString(c.stages[i].stage, sizeof c.stages[i].stage, s.stages[i].stage);
    c.stages[i].count = s.stages[i].count;
    c.stages[i].median_ms = s.stages[i].median_ms;
    c.stages[i].p99_ms = s.stages[i].p99_ms;
    c.stages[i].max_ms = s.stages[i].max_ms;
  }
  return c;
}

}  // namespace onetip::c_api
