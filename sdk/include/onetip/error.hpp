/**
 * @file onetip/error.hpp
 * @brief The exception type of the public C++ API: onetip::Error and its ErrorKind.
 *
 * The calls of Sensor, SensorOptions and the axis helpers (joystick_axes.hpp)
 * report failure by throwing onetip::Error (derived from std::runtime_error, so
 * `catch (const std::exception&)` also works) with a one-line message naming
 * what is wrong ("calibration 'x.yaml': cannot open file", "options.queue_capacity:
 * must be in [1, 64] frames, got 0") and a kind that says whose fault it is.
 * SimulatedSensor is the exception: it throws std::runtime_error
 * (simulated_sensor.hpp). The C ABI (onetip_c.h) reports the same kinds as
 * return codes: ONETIP_ERROR_INPUT, ONETIP_ERROR_STATE, ONETIP_ERROR_INTERNAL.
 */
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "onetip/export.hpp"

namespace onetip {

/// Whose fault a failure is. The values are those of the C ABI's onetip_error_kind.
enum class ErrorKind : std::uint8_t {
  input = 4,     ///< Bad input: a missing or malformed file, a bad source, an invalid option value.
  state = 5,     ///< The call is not valid now (e.g. start() twice, or from inside a callback).
  internal = 6,  ///< An unexpected failure inside the SDK (a bug: please report it).
};

/**
 * @brief The exception thrown by the public C++ API.
 *
 * what() is one line naming the bad file, key, option or call. Every internal
 * failure is translated into an Error at the API boundary; anything that is
 * not a known input or state error becomes ErrorKind::internal with a message
 * starting "internal error: ".
 */
class ONETIP_EXPORT Error : public std::runtime_error {
 public:
  /**
   * @brief Makes an error of kind `kind` with a one-line message.
   * @param kind whose fault it is.
   * @param message one line naming what is wrong; returned by what().
   */
  Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  /// @return the kind given at construction. Never throws; any thread.
  ErrorKind kind() const noexcept { return kind_; }

 private:
  ErrorKind kind_;
};

}  // namespace onetip
