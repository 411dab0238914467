#include "devices/servo_platform.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/error.hpp"
#include "devices/maestro_protocol.hpp"
#include "haptics/platform_kinematics.hpp"

namespace onetip::devices {
namespace {

constexpr int kMaestroMaxBaud = 200000;

std::vector<std::uint8_t> configurationBytes(const ServoPlatformOptions& o) {
  std::vector<std::uint8_t> bytes;
  for (int i = 0; i < 3; ++i) {
    const auto speed = maestro::setSpeed(o.channels[i], maestroSpeedUnits(o.calibration[i], o.max_speed_deg_s));
    const auto accel = maestro::setAcceleration(o.channels[i], o.acceleration);
    bytes.insert(bytes.end(), speed.begin(), speed.end());
    bytes.insert(bytes.end(), accel.begin(), accel.end());
  }
  return bytes;
}

std::vector<std::uint8_t> targetBytes(const ServoPlatformOptions& o, std::span<const double> degrees) {
  std::vector<std::uint8_t> bytes;
  for (int i = 0; i < 3; ++i) {
    const auto cmd = maestro::setTarget(o.channels[i], o.calibration[i].quarterMicroseconds(degrees[i]));
    bytes.insert(bytes.end(), cmd.begin(), cmd.end());
  }
  return bytes;
}

}  // namespace

void ServoPlatformOptions::validate() const {
  serial.validate();
  if (serial.baud > kMaestroMaxBaud) throw InputError("ServoPlatformOptions.serial.baud: the Maestro accepts at most 200000");
  std::set<int> distinct;
  for (int c : channels) {
    if (c < 0 || c > maestro::kMaxChannel) throw InputError("ServoPlatformOptions.channels: each must be in [0, 23]");
    distinct.insert(c);
  }
  if (distinct.size() != 3) throw InputError("ServoPlatformOptions.channels: must be three different channels");
  for (int i = 0; i < 3; ++i) calibration[i].validate("ServoPlatformOptions.calibration[" + std::to_string(i) + "]");
  if (!(rate_hz > 0.0 && rate_hz <= 200.0)) throw InputError("ServoPlatformOptions.rate_hz: must be in (0, 200]");
  if (!(max_speed_deg_s > 0.0 && max_speed_deg_s <= 60.0 / 0.07))
    throw InputError("ServoPlatformOptions.max_speed_deg_s: must be in (0, 857] (the servo's 60 deg in 0.07 s)");
  if (acceleration < 0 || acceleration > maestro::kMaxAcceleration)
    throw InputError("ServoPlatformOptions.acceleration: must be in [0, 255]");
  if (!(watchdog_timeout_s > 0.0 && watchdog_timeout_s <= 1.0))
    throw InputError("ServoPlatformOptions.watchdog_timeout_s: must be in (0, 1]");
}

int maestroSpeedUnits(const ServoCalibration& calibration, double max_speed_deg_s) {
  const double units = 4.0 * std::abs(calibration.us_per_deg) * max_speed_deg_s / 100.0;
  return std::clamp(static_cast<int>(std::floor(units)), 1, maestro::kMaxTarget);
}

SafeLimits servoPlatformLimits(const ServoPlatformOptions& options) {
  SafeLimits limits;
  for (int i = 0; i < 3; ++i)
    limits.outputs.push_back({"servo" + std::to_string(i + 1), "deg", haptics::kServoMinDeg, haptics::kServoMaxDeg,
                              haptics::kServoMinDeg, options.max_speed_deg_s});
  limits.command_rate_hz = options.rate_hz;
  limits.watchdog_timeout_s = options.watchdog_timeout_s;
  return limits;
}

ServoPlatform::ServoPlatform(ServoPlatformOptions options)
    : SerialDeviceLoop(options.serial, servoPlatformLimits(options), 3), options_(std::move(options)) {}

ServoPlatform::~ServoPlatform() { close(); }

void ServoPlatform::validateConfiguration() const { options_.validate(); }

void ServoPlatform::configureDevice(SerialPort& port) { port.write(configurationBytes(options_)); }

std::vector<double> ServoPlatform::outputsFor(std::span<const double> goal, double) {
  return {goal.begin(), goal.end()};
}

void ServoPlatform::sendOutputs(SerialPort& port, std::span<const double> outputs) {
  port.write(targetBytes(options_, outputs));
}

std::vector<double> ServoPlatform::readFeedback(SerialPort& port) {
  if (!options_.read_positions) return {};
  port.flushInput();
  std::vector<double> degrees;
  for (int i = 0; i < 3; ++i) {
    port.write(maestro::getPosition(options_.channels[i]));
    const std::vector<std::uint8_t> reply = port.readExact(2);
    const int qus = maestro::decodePosition(std::span<const std::uint8_t, 2>(reply.data(), 2));
    degrees.push_back(options_.calibration[i].degreesFromQuarterMicroseconds(qus));
  }
  return degrees;
}

std::array<double, 3> sendServoTargetsOnce(const ServoPlatformOptions& options, const std::array<double, 3>& degrees) {
  options.validate();
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(degrees[i])) throw InputError("angle " + std::to_string(i + 1) + ": must be a finite number");
  const std::array<double, 3> safe = haptics::clampServoAngles(degrees);
  SerialPort port;
  port.open(options.serial);
  try {
    port.write(configurationBytes(options));
    port.write(targetBytes(options, safe));
  } catch (const LinkError& e) {
    throw InputError(std::string(e.what()));
  }
  return safe;
}

}  // namespace onetip::devices
