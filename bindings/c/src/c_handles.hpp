// bindings/c/src/c_handles.hpp — the live-handle registry behind the C ABI's
// opaque onetip_sensor pointers.
//
// A handle is a unique number dressed as a pointer (0x1000, 0x1010, ... never
// reused, never dereferenced), mapped to the sensor's shared state. So a NULL,
// destroyed or made-up handle is always recognised (ONETIP_ERROR_NULL_ARGUMENT
// / ONETIP_ERROR_INVALID_HANDLE), and a call racing with destroy on another
// thread keeps the sensor alive (shared ownership) until it returns.
// Callbacks mark their thread (CallbackScope) so start/stop/destroy/wait of the
// same sensor from inside its own callback are refused instead of deadlocking,
// and count themselves per sensor (CSensor::callbacks_running) so stop/destroy
// of another sensor whose callback is running, called from a callback, is
// refused too (two callbacks stopping each other would wait on each other:
// each increments its own count before looking at the other's, so at least
// one of the two sees the other and is refused).
#pragma once

#include <atomic>
#include <memory>
#include <mutex>

#include "onetip/sensor.hpp"
#include "onetip_c.h"

namespace onetip::c_api {

struct CSensor {
  explicit CSensor(const SensorConfig& config, const SensorOptions& options) : sensor(config, options) {}
  Sensor sensor;
  std::atomic<int> callbacks_running{0};
};

// Registers a new sensor and returns its handle.
onetip_sensor* registerSensor(std::shared_ptr<CSensor> sensor);
// The sensor of a live handle; throws Error-like CError (see c_structs.hpp) for NULL or unknown handles.
std::shared_ptr<CSensor> lookupSensor(onetip_sensor* handle);
// Removes the handle; returns its sensor (to be stopped and freed by the caller) or throws like lookupSensor.
std::shared_ptr<CSensor> unregisterSensor(onetip_sensor* handle);

// Marks the current thread as running a callback of `sensor` for its lifetime.
class CallbackScope {
 public:
  explicit CallbackScope(CSensor* sensor) noexcept;
  ~CallbackScope();
  CallbackScope(const CallbackScope&) = delete;
  CallbackScope& operator=(const CallbackScope&) = delete;
  // True when the current thread is inside a callback of `sensor`.
  static bool inside(const CSensor* sensor) noexcept;
  // The sensor whose callback the current thread is running, or null.
  static const CSensor* current() noexcept;

 private:
  CSensor* sensor_;
  const CSensor* previous_;
};

}  // namespace onetip::c_api
