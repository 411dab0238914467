// bindings/c/src/c_structs.hpp — the C ABI's flat structs (onetip_c.h and
// onetip_c_uncertainty.h) from and to the public C++ types (same units and frames: mm in S, degrees, seconds), and the
// error reporting of the boundary. The options struct: c_options.hpp.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "onetip/sensor.hpp"
#include "onetip_c.h"

namespace onetip::c_api {

// An error with a C kind (NULL argument, invalid handle, version) that has no
// onetip::ErrorKind.
class CError : public std::runtime_error {
 public:
  CError(onetip_error_kind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  onetip_error_kind kind() const noexcept { return kind_; }

 private:
  onetip_error_kind kind_;
};

// Throws CError(ONETIP_ERROR_NULL_ARGUMENT) naming `what` when p is NULL.
void requireNonNull(const void* p, const char* what);
// Throws CError(ONETIP_ERROR_VERSION) when the caller's ABI version differs.
void requireAbiVersion(std::uint32_t caller_version);

// Fills `error` (may be NULL) and returns the kind.
std::int32_t reportOk(onetip_error* error) noexcept;
// Call inside a catch block: classifies the exception being handled.
std::int32_t reportCurrentException(onetip_error* error) noexcept;

// Runs an entry point's body: no exception leaves, a failure becomes its kind and message.
template <typename Fn>
std::int32_t boundary(onetip_error* error, Fn&& fn) noexcept {
  try {
    fn();
    return reportOk(error);
  } catch (...) {
    return reportCurrentException(error);
  }
}

// Copies `text` into a fixed buffer, truncated, always NUL-terminated.
void copyString(char* dst, std::size_t size, const std::string& text) noexcept;

onetip_event toC(const Event& e) noexcept;
onetip_frame toC(const FrameResult& f) noexcept;
std::vector<onetip_marker> markersToC(const FrameResult& f);
// The uncertainty forms (onetip_c_uncertainty.h): the plain struct, then sd or the stick probability.
onetip_event_sd toCWithSd(const Event& e) noexcept;
onetip_frame_sd toCWithSd(const FrameResult& f) noexcept;
std::vector<onetip_marker_sd> markersWithSdToC(const FrameResult& f);
onetip_stats toC(const SensorStats& s) noexcept;

}  // namespace onetip::c_api
