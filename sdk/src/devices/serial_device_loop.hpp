// devices/serial_device_loop.hpp — the machinery every serial fingertip
// display shares: the output gate, the watchdog, the fixed-rate command loop
// and reconnection. A driver derives from it and only says how its goal maps
// to outputs and how outputs and feedback travel on its wire protocol.
//
// The loop thread wakes every 1 / command_rate_hz s, and also exactly when
// the watchdog expires (last goal + watchdog_timeout_s) or an input error is
// reported, so retraction is not delayed to the next period. Per wake-up:
//   1. feedback = readFeedback()                     (driver)
//   2. stale (no goal yet, goal older than the timeout, input error, refused
//      goal) -> outputs = rest, onRetract()          (once per stall: counted)
//      else   -> outputs = gate(outputsFor(goal))    (driver, then OutputGate)
//   3. sendOutputs(outputs)                          (driver)
// A LinkError in any step marks the link down; the loop then reopens the same
// port every reconnect_interval_s, runs configureDevice() again and restarts
// from rest (the device may have reset), ramping to the goal at the rate limit.
// Derived classes must call close() in their destructor (the loop calls their
// virtual functions).
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "devices/cutaneous_device.hpp"
#include "devices/output_gate.hpp"
#include "devices/serial_port.hpp"

namespace onetip::devices {

class SerialDeviceLoop : public CutaneousDevice {
 public:
  ~SerialDeviceLoop() override;
  void open() final;
  void command(std::span<const double> goal) final;
  void reportInputError(const std::string& why) final;
  DeviceStatus status() const final;
  void close() final;
  const SafeLimits& limits() const final { return limits_; }
  size_t goalSize() const final { return goal_size_; }

 protected:
  SerialDeviceLoop(SerialOptions serial, SafeLimits limits, size_t goal_size, double reconnect_interval_s = 0.1);

  // Checks the driver's own configuration (InputError naming the item).
  virtual void validateConfiguration() const = 0;
  // After every (re)open, before the first outputs: e.g. speed limits.
  virtual void configureDevice(SerialPort& port) = 0;
  // The outputs wanted for a finite goal; the gate then limits them.
  virtual std::vector<double> outputsFor(std::span<const double> goal, double dt_s) = 0;
  virtual void sendOutputs(SerialPort& port, std::span<const double> outputs) = 0;
  // Feedback in output units (empty when none arrived); default: none.
  virtual std::vector<double> readFeedback(SerialPort& port);
  // Called when the outputs jump to rest (reset controllers).
  virtual void onRetract() {}

  const SerialOptions& serialOptions() const noexcept { return serial_; }

 private:
  using Clock = std::chrono::steady_clock;
  void loop();
  void tick(Clock::time_point now, std::unique_lock<std::mutex>& lock);
  void linkDown(const std::string& why);

  SerialOptions serial_;
  SafeLimits limits_;
  size_t goal_size_;
  Clock::duration reconnect_interval_;
  SerialPort port_;  // used by the loop thread only (and open/close)
  OutputGate gate_;

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::thread thread_;
  bool stop_ = false;
  std::vector<double> goal_;
  bool goal_valid_ = false;          // a finite goal, not yet stale
  bool input_error_ = false;
  Clock::time_point last_goal_{};
  Clock::time_point next_reconnect_{};
  DeviceStatus status_;
};

}  // namespace onetip::devices
