// bindings/c/src/onetip_c_uncertainty.cpp — the entry points of minor version 2
// (onetip_c_uncertainty.h): poll, wait and the callbacks with the uncertainty
// of the 6-D input and the markers' stick probability. Same bodies as their
// plain forms in onetip_c.cpp (c_sensor_calls.hpp), other structs.
#include "c_sensor_calls.hpp"
#include "c_structs.hpp"
#include "onetip_c.h"

using namespace onetip;
using namespace onetip::c_api;

extern "C" {

ONETIP_C_API int32_t onetip_sensor_poll_event_sd(onetip_sensor* sensor, onetip_event_sd* out, int32_t* got,
                                                 onetip_error* error) {
  return pollEventInto(sensor, out, got, error, "onetip_sensor_poll_event_sd",
                       [](const Event& e) { return toCWithSd(e); });
}

ONETIP_C_API int32_t onetip_sensor_wait_event_sd(onetip_sensor* sensor, double timeout_s, onetip_event_sd* out,
                                                 int32_t* got, onetip_error* error) {
  return waitEventInto(sensor, timeout_s, out, got, error, "onetip_sensor_wait_event_sd",
                       [](const Event& e) { return toCWithSd(e); });
}

ONETIP_C_API int32_t onetip_sensor_poll_frame_sd(onetip_sensor* sensor, onetip_frame_sd* out, onetip_marker_sd* markers,
                                                 int32_t capacity, int32_t* marker_count, int32_t* got,
                                                 onetip_error* error) {
  return pollFrameInto(
      sensor, out, markers, capacity, marker_count, got, error, "onetip_sensor_poll_frame_sd",
      [](const FrameResult& f) { return toCWithSd(f); }, markersWithSdToC);
}

ONETIP_C_API int32_t onetip_sensor_set_event_sd_callback(onetip_sensor* sensor, onetip_event_sd_callback callback,
                                                         void* user, onetip_error* error) {
  return setEventCallbackTo(sensor, callback, user, error, [](const Event& e) { return toCWithSd(e); });
}

ONETIP_C_API int32_t onetip_sensor_set_frame_sd_callback(onetip_sensor* sensor, onetip_frame_sd_callback callback,
                                                         void* user, onetip_error* error) {
  return setFrameCallbackTo(
      sensor, callback, user, error, [](const FrameResult& f) { return toCWithSd(f); }, markersWithSdToC);
}

}  // extern "C"
