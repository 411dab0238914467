// bindings/c/src/c_sensor_calls.hpp — the bodies of the C ABI's poll, wait and
// callback entry points, shared by their plain form (onetip_c.h: onetip_event,
// onetip_frame, onetip_marker) and their uncertainty form (onetip_c_uncertainty.h:
// onetip_event_sd, onetip_frame_sd, onetip_marker_sd). Each takes the name of
// its entry point for its messages and a conversion from the C++ value to the
// C struct (c_structs.hpp); the rules are those of onetip_c.h.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "c_handles.hpp"
#include "c_structs.hpp"
#include "onetip_c.h"

namespace onetip::c_api {

// Throws CError(ONETIP_ERROR_STATE) when the current thread runs a callback of `s`.
void refuseInsideCallback(const CSensor& s, const char* call);
// A time-out in seconds: NaN is an input error; < 0, INFINITY and >= 1e9 mean no limit, returned as -1.
double waitTimeout(double timeout_s, const char* call);
// Sensor::waitEvent for up to `timeout` seconds (-1: no limit); true when an event was taken.
bool waitForEvent(Sensor& sensor, Event& e, double timeout);
// Throws CError(ONETIP_ERROR_NULL_ARGUMENT) naming "<call>: <what>" when p is NULL.
void requireArgument(const void* p, const char* call, const char* what);

template <typename CEvent, typename Convert>
std::int32_t pollEventInto(onetip_sensor* sensor, CEvent* out, std::int32_t* got, onetip_error* error, const char* call,
                           Convert convert) noexcept {
  if (got) *got = 0;
  return boundary(error, [&] {
    requireArgument(out, call, "out");
    requireArgument(got, call, "got");
    Event e;
    if (lookupSensor(sensor)->sensor.pollEvent(e)) {
      *out = convert(e);
      *got = 1;
    }
  });
}

template <typename CEvent, typename Convert>
std::int32_t waitEventInto(onetip_sensor* sensor, double timeout_s, CEvent* out, std::int32_t* got, onetip_error* error,
                           const char* call, Convert convert) noexcept {
  if (got) *got = 0;
  return boundary(error, [&] {
    requireArgument(out, call, "out");
    requireArgument(got, call, "got");
    const auto s = lookupSensor(sensor);
    refuseInsideCallback(*s, call);
    Event e;
    if (waitForEvent(s->sensor, e, waitTimeout(timeout_s, call))) {
      *out = convert(e);
      *got = 1;
    }
  });
}

// ConvertMarkers: const FrameResult& -> std::vector<CMarker>, indexed by id.
template <typename CFrame, typename CMarker, typename ConvertFrame, typename ConvertMarkers>
std::int32_t pollFrameInto(onetip_sensor* sensor, CFrame* out, CMarker* markers, std::int32_t capacity,
                           std::int32_t* marker_count, std::int32_t* got, onetip_error* error, const char* call,
                           ConvertFrame convert_frame, ConvertMarkers convert_markers) noexcept {
  if (got) *got = 0;
  if (marker_count) *marker_count = 0;
  return boundary(error, [&] {
    requireArgument(out, call, "out");
    requireArgument(got, call, "got");
    requireArgument(marker_count, call, "marker_count");
    if (capacity < 0) throw Error(ErrorKind::input, std::string(call) + ": capacity is negative");
    if (capacity > 0) requireArgument(markers, call, "markers (capacity > 0)");
    FrameResult f;
    if (!lookupSensor(sensor)->sensor.pollFrame(f)) return;
    *out = convert_frame(f);
    *marker_count = static_cast<std::int32_t>(f.markers.size());
    if (capacity > 0) {
      const std::vector<CMarker> all = convert_markers(f);
      std::copy_n(all.begin(), std::min<std::size_t>(all.size(), static_cast<std::size_t>(capacity)), markers);
    }
    *got = 1;
  });
}

// Callback: void (*)(const CEvent*, void*).
template <typename Callback, typename Convert>
std::int32_t setEventCallbackTo(onetip_sensor* sensor, Callback callback, void* user, onetip_error* error,
                                Convert convert) noexcept {
  return boundary(error, [&] {
    const auto s = lookupSensor(sensor);
    if (!callback) return s->sensor.onEvent({});
    CSensor* owner = s.get();
    s->sensor.onEvent([callback, user, owner, convert](const Event& e) {
      const auto c = convert(e);
      CallbackScope scope(owner);
      callback(&c, user);
    });
  });
}

// Callback: void (*)(const CFrame*, const CMarker*, int32_t, void*).
template <typename Callback, typename ConvertFrame, typename ConvertMarkers>
std::int32_t setFrameCallbackTo(onetip_sensor* sensor, Callback callback, void* user, onetip_error* error,
                                ConvertFrame convert_frame, ConvertMarkers convert_markers) noexcept {
  return boundary(error, [&] {
    const auto s = lookupSensor(sensor);
    if (!callback) return s->sensor.onFrame({});
    CSensor* owner = s.get();
    s->sensor.onFrame([callback, user, owner, convert_frame, convert_markers](const FrameResult& f) {
      const auto c = convert_frame(f);
      const auto markers = convert_markers(f);
      CallbackScope scope(owner);
      callback(&c, markers.data(), static_cast<std::int32_t>(markers.size()), user);
    });
  });
}

}  // namespace onetip::c_api
