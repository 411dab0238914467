#include "devices/wire_device.hpp"

#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/rotation.hpp"
#include "devices/imu_orientation.hpp"

namespace onetip::devices {
namespace {

SafeLimits wireLimits(const WireDeviceOptions& o) {
  SafeLimits limits;
  for (int i = 0; i < 3; ++i) limits.outputs.push_back({"pwm" + std::to_string(i + 1), "duty", 0.0, 1.0, 0.0, o.max_pwm_rate});
  limits.command_rate_hz = o.rate_hz;
  limits.watchdog_timeout_s = o.watchdog_timeout_s;
  return limits;
}

Eigen::Vector3d vec(std::span<const std::uint8_t> p, size_t at, double scale) {
  return {frame::getI16(p, at) * scale, frame::getI16(p, at + 2) * scale, frame::getI16(p, at + 4) * scale};
}

}  // namespace

void WireDeviceOptions::validate() const {
  serial.validate();
  geometry.validate();
  controller.validate();
  if (!(tension_at_full_pwm_n > 0.0 && tension_at_full_pwm_n < 100.0))
    throw InputError("WireDeviceOptions.tension_at_full_pwm_n: must be in (0, 100)");
  if (!(body_mag_offset_ut.allFinite() && plate_mag_offset_ut.allFinite()))
    throw InputError("WireDeviceOptions.*_mag_offset_ut: must be finite");
  if (!(max_force_n > 0.0 && max_force_n <= 5.0)) throw InputError("WireDeviceOptions.max_force_n: must be in (0, 5]");
  if (!(max_tilt_deg >= 0.0 && max_tilt_deg < 60.0)) throw InputError("WireDeviceOptions.max_tilt_deg: must be in [0, 60)");
  if (!(rate_hz >= 10.0 && rate_hz <= 1000.0)) throw InputError("WireDeviceOptions.rate_hz: must be in [10, 1000]");
  if (!(max_pwm_rate > 0.0)) throw InputError("WireDeviceOptions.max_pwm_rate: must be positive");
  if (!(sensor_timeout_s > 0.0 && sensor_timeout_s <= 1.0)) throw InputError("WireDeviceOptions.sensor_timeout_s: must be in (0, 1]");
  if (!(watchdog_timeout_s > 0.0 && watchdog_timeout_s <= 1.0))
    throw InputError("WireDeviceOptions.watchdog_timeout_s: must be in (0, 1]");
}

Eigen::Vector3d limitWireForce(const Eigen::Vector3d& fd, double max_force_n, double max_tilt_deg) {
  Eigen::Vector3d f = fd;
  f.z() = std::clamp(f.z(), 0.0, max_force_n);
  const double lateral = f.head<2>().norm();
  const double allowed = f.z() * std::tan(max_tilt_deg * kRadPerDeg);
  if (lateral > allowed) f.head<2>() *= lateral > 0.0 ? allowed / lateral : 0.0;
  if (f.norm() > max_force_n) f *= max_force_n / f.norm();
  return f;
}

WireDevice::WireDevice(WireDeviceOptions options)
    : SerialDeviceLoop(options.serial, wireLimits(options), 3),
      options_(std::move(options)),
      controller_(options_.geometry, options_.controller) {}

WireDevice::~WireDevice() { close(); }

void WireDevice::validateConfiguration() const { options_.validate(); }

void WireDevice::configureDevice(SerialPort&) {
  parser_ = frame::Parser{};
  sensors_.reset();
  controller_.reset();
}

std::vector<double> WireDevice::outputsFor(std::span<const double> goal, double dt_s) {
  const auto now = std::chrono::steady_clock::now();
  if (!sensors_ || now - sensors_->received > std::chrono::duration<double>(options_.sensor_timeout_s))
    return std::vector<double>(3, std::numeric_limits<double>::quiet_NaN());  // sensor stall: retract
  const Eigen::Vector3d fd = limitWireForce({goal[0], goal[1], goal[2]}, options_.max_force_n, options_.max_tilt_deg);
  const Eigen::Vector3d u = controller_.step(fd, sensors_->plate_rotation, sensors_->fsr_n, dt_s);
  return {u(0) / options_.tension_at_full_pwm_n, u(1) / options_.tension_at_full_pwm_n,
          u(2) / options_.tension_at_full_pwm_n};
}

void WireDevice::sendOutputs(SerialPort& port, std::span<const double> outputs) {
  std::vector<std::uint8_t> payload;
  for (double duty : outputs) frame::putU16(payload, static_cast<std::uint16_t>(std::lround(duty * 1000.0)));
  port.write(frame::encode(wire::kSetPwm, payload));
}

std::vector<double> WireDevice::readFeedback(SerialPort& port) {
  const std::vector<std::uint8_t> bytes = port.readAvailable(0);
  parser_.feed(bytes, [&](const frame::Frame& f) {
    if (f.type != wire::kSensors || f.payload.size() != 28) return;
    const std::span<const std::uint8_t> p(f.payload);
    try {
      const Eigen::Matrix3d body = orientationFromAccelMag(vec(p, 4, 1e-3), vec(p, 10, 0.01) - options_.body_mag_offset_ut);
      const Eigen::Matrix3d plate = orientationFromAccelMag(vec(p, 16, 1e-3), vec(p, 22, 0.01) - options_.plate_mag_offset_ut);
      sensors_ = Sensors{frame::getU16(p, 2) * 1e-3, body.transpose() * plate, std::chrono::steady_clock::now()};
    } catch (const InputError&) {
      // a degenerate IMU reading: keep the previous frame (the stall timeout covers a dead sensor)
    }
  });
  if (!sensors_) return {};
  const Eigen::Vector3d f = controller_.estimatedForce();
  return {f(0), f(1), f(2)};
}

}  // namespace onetip::devices
