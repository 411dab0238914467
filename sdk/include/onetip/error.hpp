// onetip/error.hpp — the one exception type the public C++ API throws.
//
// Every failing call of the public API throws onetip::Error (derived from
// std::runtime_error, so `catch (const std::exception&)` also works) with a
// one-line message naming what is wrong ("calibration 'x.yaml': cannot open
// file", "options.queue_capacity: must be in [1, 64] frames, got 0") and a
// kind that says whose fault it is. The C ABI (onetip_c.h) reports the same kinds as codes.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "onetip/export.hpp"

namespace onetip {

enum class ErrorKind : std::uint8_t {
  input = 4,     // bad input: a missing or malformed file, a bad source, an invalid option value
  state = 5,     // the call is not valid now (e.g. start() from inside a callback)
  internal = 6,  // an unexpected failure inside the SDK (a bug: please report it)
};

class ONETIP_EXPORT Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  ErrorKind kind() const noexcept { return kind_; }

 private:
  ErrorKind kind_;
};

}  // namespace onetip
