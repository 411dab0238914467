// bindings/c/src/onetip_c.cpp — the C ABI (onetip_c.h) over the public C++
// API. Every entry point runs its body inside boundary(): no exception leaves,
// each failure becomes an onetip_error_kind and a message. The options
// functions are in c_options.cpp, the uncertainty forms of poll, wait and the
// callbacks in onetip_c_uncertainty.cpp (both forms share c_sensor_calls.hpp).
#include "c_handles.hpp"
#include "c_options.hpp"
#include "c_sensor_calls.hpp"
#include "c_structs.hpp"
#include "onetip/version.hpp"
#include "onetip_c.h"

using namespace onetip;
using namespace onetip::c_api;

namespace {

std::string optionalString(const char* s) { return s ? std::string(s) : std::string(); }

// stop/destroy wait for the sensor's processing thread, hence for its running callback.
void refuseStopFromCallback(const CSensor& s, const char* call) {
  refuseInsideCallback(s, call);
  if (CallbackScope::current() && s.callbacks_running.load() > 0)
    throw CError(ONETIP_ERROR_STATE, std::string(call) +
                                         ": called from another sensor's callback while this sensor's callback is "
                                         "running (the two would wait on each other)");
}

}  // namespace

extern "C" {

ONETIP_C_API uint32_t onetip_abi_version(void) { return ONETIP_C_ABI_VERSION; }
ONETIP_C_API const char* onetip_version_string(void) { return versionString(); }
ONETIP_C_API double onetip_clock_seconds(void) { return clockSeconds(); }

ONETIP_C_API const char* onetip_error_kind_name(int32_t kind) {
  static const char* const names[] = {"ok", "null_argument", "invalid_handle", "version", "input", "state", "internal"};
  return kind >= 0 && kind < 7 ? names[kind] : "unknown";
}

ONETIP_C_API const char* onetip_event_type_name(int32_t type) {
  return type >= 0 && type <= ONETIP_EVENT_ERROR ? toString(static_cast<EventType>(type)).data() : "unknown";
}

ONETIP_C_API const char* onetip_contact_state_name(int32_t state) {
  return state >= 0 && state <= ONETIP_STATE_SLIP ? toString(static_cast<ContactState>(state)).data() : "unknown";
}

ONETIP_C_API int32_t onetip_sensor_create(uint32_t abi_version, const char* source, const char* calibration,
                                          const char* pattern, const char* reference, const onetip_options* options,
                                          onetip_sensor** out, onetip_error* error) {
  if (out) *out = nullptr;
  return boundary(error, [&] {
    requireAbiVersion(abi_version);
    requireNonNull(out, "onetip_sensor_create: out");
    requireNonNull(source, "onetip_sensor_create: source");
    const SensorOptions o = options ? fromC(*options) : SensorOptions{};
    const SensorConfig config{source, optionalString(calibration), optionalString(pattern), optionalString(reference)};
    *out = registerSensor(std::make_shared<CSensor>(config, o));
  });
}

ONETIP_C_API int32_t onetip_sensor_destroy(onetip_sensor* sensor, onetip_error* error) {
  return boundary(error, [&] {
    if (!sensor) return;
    refuseStopFromCallback(*lookupSensor(sensor), "onetip_sensor_destroy");
    std::shared_ptr<CSensor> s = unregisterSensor(sensor);
    s->sensor.stop();
  });
}

ONETIP_C_API int32_t onetip_sensor_start(onetip_sensor* sensor, onetip_error* error) {
  return boundary(error, [&] {
    const auto s = lookupSensor(sensor);
    refuseInsideCallback(*s, "onetip_sensor_start");
    s->sensor.start();
  });
}

ONETIP_C_API int32_t onetip_sensor_stop(onetip_sensor* sensor, onetip_error* error) {
  return boundary(error, [&] {
    const auto s = lookupSensor(sensor);
    refuseStopFromCallback(*s, "onetip_sensor_stop");
    s->sensor.stop();
  });
}

ONETIP_C_API int32_t onetip_sensor_is_running(onetip_sensor* sensor, int32_t* out, onetip_error* error) {
  return boundary(error, [&] {
    requireNonNull(out, "onetip_sensor_is_running: out");
    *out = lookupSensor(sensor)->sensor.running() ? 1 : 0;
  });
}

ONETIP_C_API int32_t onetip_sensor_is_finished(onetip_sensor* sensor, int32_t* out, onetip_error* error) {
  return boundary(error, [&] {
    requireNonNull(out, "onetip_sensor_is_finished: out");
    *out = lookupSensor(sensor)->sensor.finished() ? 1 : 0;
  });
}

ONETIP_C_API int32_t onetip_sensor_wait_finished(onetip_sensor* sensor, double timeout_s, int32_t* finished,
                                                 onetip_error* error) {
  return boundary(error, [&] {
    requireNonNull(finished, "onetip_sensor_wait_finished: finished");
    *finished = 0;
    const auto s = lookupSensor(sensor);
    refuseInsideCallback(*s, "onetip_sensor_wait_finished");
    *finished = s->sensor.waitFinished(waitTimeout(timeout_s, "onetip_sensor_wait_finished")) ? 1 : 0;
  });
}

ONETIP_C_API int32_t onetip_sensor_set_event_callback(onetip_sensor* sensor, onetip_event_callback callback,
                                                      void* user, onetip_error* error) {
  return setEventCallbackTo(sensor, callback, user, error, [](const Event& e) { return toC(e); });
}

ONETIP_C_API int32_t onetip_sensor_set_frame_callback(onetip_sensor* sensor, onetip_frame_callback callback,
                                                      void* user, onetip_error* error) {
  return setFrameCallbackTo(sensor, callback, user, error, [](const FrameResult& f) { return toC(f); }, markersToC);
}

ONETIP_C_API int32_t onetip_sensor_poll_event(onetip_sensor* sensor, onetip_event* out, int32_t* got,
                                              onetip_error* error) {
  return pollEventInto(sensor, out, got, error, "onetip_sensor_poll_event", [](const Event& e) { return toC(e); });
}

ONETIP_C_API int32_t onetip_sensor_wait_event(onetip_sensor* sensor, double timeout_s, onetip_event* out,
                                              int32_t* got, onetip_error* error) {
  return waitEventInto(sensor, timeout_s, out, got, error, "onetip_sensor_wait_event",
                       [](const Event& e) { return toC(e); });
}

ONETIP_C_API int32_t onetip_sensor_poll_frame(onetip_sensor* sensor, onetip_frame* out, onetip_marker* markers,
                                              int32_t capacity, int32_t* marker_count, int32_t* got,
                                              onetip_error* error) {
  return pollFrameInto(sensor, out, markers, capacity, marker_count, got, error, "onetip_sensor_poll_frame",
                       [](const FrameResult& f) { return toC(f); }, markersToC);
}

ONETIP_C_API int32_t onetip_sensor_rezero(onetip_sensor* sensor, onetip_error* error) {
  return boundary(error, [&] { lookupSensor(sensor)->sensor.reZero(); });
}

ONETIP_C_API int32_t onetip_sensor_rereference(onetip_sensor* sensor, onetip_error* error) {
  return boundary(error, [&] { lookupSensor(sensor)->sensor.reReference(); });
}

ONETIP_C_API int32_t onetip_sensor_get_stats(onetip_sensor* sensor, onetip_stats* out, onetip_error* error) {
  return boundary(error, [&] {
    requireNonNull(out, "onetip_sensor_get_stats: out");
    *out = toC(lookupSensor(sensor)->sensor.stats());
  });
}

}  // extern "C"
