#include "devices/serial_device_loop.hpp"

#include <cmath>

#include "core/error.hpp"

namespace onetip::devices {

SerialDeviceLoop::SerialDeviceLoop(SerialOptions serial, SafeLimits limits, size_t goal_size,
                                   double reconnect_interval_s)
    : serial_(std::move(serial)),
      limits_(std::move(limits)),
      goal_size_(goal_size),
      reconnect_interval_(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(reconnect_interval_s))),
      gate_(limits_) {
  status_.outputs = limits_.rest();
}

SerialDeviceLoop::~SerialDeviceLoop() { close(); }

void SerialDeviceLoop::open() {
  close();
  limits_.validate();
  serial_.validate();
  validateConfiguration();
  port_.open(serial_);  // InputError for a missing or non-terminal port
  try {
    configureDevice(port_);
    sendOutputs(port_, gate_.retract());
  } catch (const LinkError& e) {
    port_.close();
    throw InputError("port '" + serial_.port + "': the device does not answer (" + e.what() + ")");
  }
  std::lock_guard lock(mutex_);
  status_ = DeviceStatus{};
  status_.open = status_.connected = status_.retracted = true;
  status_.outputs = gate_.outputs();
  goal_valid_ = input_error_ = stop_ = false;
  thread_ = std::thread([this] { loop(); });
}

void SerialDeviceLoop::close() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
  if (port_.isOpen()) {
    try {
      sendOutputs(port_, gate_.retract());
    } catch (const LinkError&) {
      // the link is gone: nothing more can be sent
    }
    port_.close();
  }
  std::lock_guard lock(mutex_);
  status_.open = status_.connected = false;
}

void SerialDeviceLoop::command(std::span<const double> goal) {
  std::lock_guard lock(mutex_);
  if (goal.size() != goal_size_ || !allFinite(goal)) {
    ++status_.goals_refused;
    goal_valid_ = false;
    input_error_ = true;
  } else {
    goal_.assign(goal.begin(), goal.end());
    goal_valid_ = true;
    input_error_ = false;
    last_goal_ = Clock::now();
  }
  wake_.notify_all();
}

void SerialDeviceLoop::reportInputError(const std::string&) {
  std::lock_guard lock(mutex_);
  input_error_ = true;
  goal_valid_ = false;
  wake_.notify_all();
}

DeviceStatus SerialDeviceLoop::status() const {
  std::lock_guard lock(mutex_);
  return status_;
}

std::vector<double> SerialDeviceLoop::readFeedback(SerialPort&) { return {}; }

void SerialDeviceLoop::loop() {
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / limits_.command_rate_hz));
  const auto timeout =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits_.watchdog_timeout_s));
  std::unique_lock lock(mutex_);
  auto next_tick = Clock::now();
  while (!stop_) {
    // Wake at the next period, or when the watchdog would expire, or on news.
    auto wake_at = next_tick;
    if (goal_valid_ && last_goal_ + timeout < wake_at) wake_at = last_goal_ + timeout;
    wake_.wait_until(lock, wake_at, [&] { return stop_ || (input_error_ && !status_.retracted); });
    if (stop_) break;
    const auto now = Clock::now();
    tick(now, lock);
    if (now >= next_tick) next_tick = std::max(next_tick + period, now);
  }
}

void SerialDeviceLoop::tick(Clock::time_point now, std::unique_lock<std::mutex>& lock) {
  const auto timeout =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits_.watchdog_timeout_s));
  if (goal_valid_ && now - last_goal_ >= timeout) goal_valid_ = false;
  const bool stale = !goal_valid_;
  const std::vector<double> goal = goal_;
  const bool was_retracted = status_.retracted;
  const bool connected = status_.connected;
  lock.unlock();

  std::string failure;
  std::vector<double> feedback;
  bool reconnected = false;
  bool refused = false;
  const std::vector<double>* out = nullptr;
  try {
    if (!connected) {
      if (now < next_reconnect_) {
        lock.lock();
        return;
      }
      next_reconnect_ = now + reconnect_interval_;
      port_.reopen();
      configureDevice(port_);
      reconnected = true;
      onRetract();
      out = &gate_.retract();
    }
    feedback = readFeedback(port_);
    if (stale) {
      if (!was_retracted) onRetract();
      out = &gate_.retract();
    } else if (!reconnected) {
      const std::vector<double> want = outputsFor(goal, 1.0 / limits_.command_rate_hz);
      if (allFinite(want) && want.size() == gate_.outputs().size()) {
        out = &gate_.step(want);
      } else {  // the driver cannot compute outputs (e.g. its sensors stalled)
        onRetract();
        out = &gate_.retract();
        refused = true;
      }
    }
    sendOutputs(port_, *out);
  } catch (const LinkError& e) {
    failure = e.what();
    port_.close();
    gate_.retract();  // the device may reset while the link is down: restart from rest
    onRetract();
  }

  lock.lock();
  if (!failure.empty()) {
    status_.connected = false;
    status_.retracted = true;
    status_.last_error = failure;
    return;
  }
  if (reconnected) {
    status_.connected = true;
    ++status_.reconnects;
  }
  if (stale && !was_retracted) ++status_.retractions;
  status_.retracted = stale || refused;
  status_.outputs = *out;
  if (!feedback.empty()) status_.measured = feedback;
  ++status_.commands_sent;
}

}  // namespace onetip::devices
