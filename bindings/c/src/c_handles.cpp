#include "c_handles.hpp"

#include <cstdint>
#include <cstdio>
#include <unordered_map>

#include "c_structs.hpp"

namespace onetip::c_api {
namespace {

struct Registry {
  std::mutex mutex;
  std::uintptr_t next = 0x1000;
  std::unordered_map<std::uintptr_t, std::shared_ptr<CSensor>> sensors;
};

Registry& registry() {
  static Registry* r = new Registry;  // never destroyed: callable during static destruction
  return *r;
}

std::uintptr_t keyOf(onetip_sensor* handle) {
  requireNonNull(handle, "sensor handle");
  return reinterpret_cast<std::uintptr_t>(handle);
}

[[noreturn]] void invalidHandle(std::uintptr_t key) {
  char text[32];
  std::snprintf(text, sizeof text, "%#llx", static_cast<unsigned long long>(key));
  throw CError(ONETIP_ERROR_INVALID_HANDLE,
               std::string("sensor handle ") + text + ": not a live sensor (destroyed, or not from onetip_sensor_create)");
}

thread_local const CSensor* current_callback_sensor = nullptr;

}  // namespace

onetip_sensor* registerSensor(std::shared_ptr<CSensor> sensor) {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  const std::uintptr_t key = r.next;
  r.next += 0x10;
  r.sensors.emplace(key, std::move(sensor));
  return reinterpret_cast<onetip_sensor*>(key);
}

std::shared_ptr<CSensor> lookupSensor(onetip_sensor* handle) {
  const std::uintptr_t key = keyOf(handle);
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  const auto it = r.sensors.find(key);
  if (it == r.sensors.end()) invalidHandle(key);
  return it->second;
}

std::shared_ptr<CSensor> unregisterSensor(onetip_sensor* handle) {
  const std::uintptr_t key = keyOf(handle);
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  const auto it = r.sensors.find(key);
  if (it == r.sensors.end()) invalidHandle(key);
  if (CallbackScope::inside(it->second.get()))
    throw CError(ONETIP_ERROR_STATE, "onetip_sensor_destroy: called from inside the sensor's own callback");
  std::shared_ptr<CSensor> s = std::move(it->second);
  r.sensors.erase(it);
  return s;
}

CallbackScope::CallbackScope(CSensor* sensor) noexcept : sensor_(sensor), previous_(current_callback_sensor) {
  sensor_->callbacks_running.fetch_add(1);
  current_callback_sensor = sensor;
}
CallbackScope::~CallbackScope() {
  current_callback_sensor = previous_;
  sensor_->callbacks_running.fetch_sub(1);
}
bool CallbackScope::inside(const CSensor* sensor) noexcept { return current_callback_sensor == sensor; }
const CSensor* CallbackScope::current() noexcept { return current_callback_sensor; }

}  // namespace onetip::c_api
