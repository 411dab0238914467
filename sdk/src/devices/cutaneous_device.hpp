// devices/cutaneous_device.hpp — the one small interface every fingertip
// display driver implements, and the description of its safe output range.
//
// A driver takes a goal in its own task units (servo angles in degrees, belt
// forces in N, wire-device force vector in N: see each driver's header) and
// turns it into hardware targets ("outputs": servo angles, motor angles, PWM
// duty) that never leave SafeLimits, whatever the goal: non-finite goals are
// refused (the device retracts, as for reportInputError), finite ones are
// clamped into range and every step between two consecutive outputs is at
// most max_rate / command_rate_hz. The only exception is retraction: the
// watchdog sends the rest outputs at once (moving away from the finger is
// always safe; the actuators' own speed limits then govern the motion).
// The watchdog retracts when no goal came for watchdog_timeout_s or when the
// input reports an error, and holds rest until the next valid goal.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace onetip::devices {

struct OutputLimit {
  std::string name;   // e.g. "servo1"
  std::string unit;   // e.g. "deg"
  double min = 0.0;
  double max = 0.0;
  double rest = 0.0;  // the retracted output, inside [min, max]
  double max_rate = std::numeric_limits<double>::infinity();  // unit per second
};

struct SafeLimits {
  std::vector<OutputLimit> outputs;
  double command_rate_hz = 50.0;
  double watchdog_timeout_s = 0.1;
  void validate() const;  // throws InputError naming the bad field
  // The largest allowed step of output i between two consecutive commands.
  double maxStep(size_t i) const { return outputs[i].max_rate / command_rate_hz; }
  std::vector<double> rest() const;
};

struct DeviceStatus {
  bool open = false;
  bool connected = false;        // the link is up now
  bool retracted = true;         // the outputs are (being held) at rest
  std::vector<double> outputs;   // the last outputs sent (SafeLimits units)
  std::vector<double> measured;  // the device's feedback, in units its driver documents
  std::uint64_t commands_sent = 0;
  std::uint64_t goals_refused = 0;  // non-finite goals
  std::uint64_t retractions = 0;
  std::uint64_t reconnects = 0;
  std::string last_error;        // the last link failure, empty when none
};

class CutaneousDevice {
 public:
  virtual ~CutaneousDevice() = default;
  // Checks every configuration item and opens the link; InputError naming the
  // bad item (options, port, baud, calibration table) before anything is sent.
  virtual void open() = 0;
  // The latest goal; goal.size() == goalSize(). Thread-safe, never blocks on I/O.
  virtual void command(std::span<const double> goal) = 0;
  // The input failed (tracking lost, sensor error): retract now.
  virtual void reportInputError(const std::string& why) = 0;
  virtual DeviceStatus status() const = 0;
  virtual void close() = 0;
  virtual const SafeLimits& limits() const = 0;
  virtual size_t goalSize() const = 0;
};

}  // namespace onetip::devices
