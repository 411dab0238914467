#include "devices/belt_device.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace onetip::devices {
namespace {

SafeLimits beltLimits(const BeltDeviceOptions& o, double max_angle) {
  SafeLimits limits;
  limits.outputs = {{"motor1", "deg", -max_angle, max_angle, 0.0, o.max_speed_deg_s},
                    {"motor2", "deg", -max_angle, max_angle, 0.0, o.max_speed_deg_s}};
  limits.command_rate_hz = o.rate_hz;
  limits.watchdog_timeout_s = o.watchdog_timeout_s;
  return limits;
}

}  // namespace

void BeltDeviceOptions::validate() const {
  serial.validate();
  if (!(max_force_n > 0.0 && max_force_n <= 20.0)) throw InputError("BeltDeviceOptions.max_force_n: must be in (0, 20]");
  if (!(rate_hz >= 10.0 && rate_hz <= 2000.0)) throw InputError("BeltDeviceOptions.rate_hz: must be in [10, 2000]");
  if (feedback_rate_hz < 1 || feedback_rate_hz > 1000)
    throw InputError("BeltDeviceOptions.feedback_rate_hz: must be in [1, 1000]");
  if (!(max_speed_deg_s > 0.0 && max_speed_deg_s <= 5000.0))
    throw InputError("BeltDeviceOptions.max_speed_deg_s: must be in (0, 5000]");
  if (!(counts_per_rev >= 4.0)) throw InputError("BeltDeviceOptions.counts_per_rev: must be at least 4");
  if (!(watchdog_timeout_s > 0.0 && watchdog_timeout_s <= 1.0))
    throw InputError("BeltDeviceOptions.watchdog_timeout_s: must be in (0, 1]");
  loadTable();
}

BeltForceTable BeltDeviceOptions::loadTable() const {
  if (!force_table_csv.empty()) return BeltForceTable::load(force_table_csv);
  return BeltForceTable::fromPoints(force_points, "BeltDeviceOptions.force_points");
}

BeltDevice::BeltDevice(BeltDeviceOptions options)
    : SerialDeviceLoop(options.serial, beltLimits(options, options.loadTable().maxAngle()), 2),
      options_(std::move(options)),
      table_(options_.loadTable()) {}

BeltDevice::~BeltDevice() { close(); }

void BeltDevice::validateConfiguration() const { options_.validate(); }

std::array<double, 2> BeltDevice::motorAngles(const BeltForceTable& table, double max_force_n, double normal_n,
                                              double shear_n) {
  const double theta_n = table.angleFor(normal_n / max_force_n);
  const double room = table.maxAngle() - theta_n;
  const double theta_s = std::copysign(std::min(table.angleFor(std::abs(shear_n) / max_force_n), room), shear_n);
  return {theta_n + theta_s, -theta_n + theta_s};
}

void BeltDevice::configureDevice(SerialPort& port) {
  parser_ = frame::Parser{};
  std::vector<std::uint8_t> payload;
  frame::putU16(payload, static_cast<std::uint16_t>(options_.feedback_rate_hz));
  port.write(frame::encode(belt::kSetFeedbackRate, payload));
}

std::vector<double> BeltDevice::outputsFor(std::span<const double> goal, double) {
  const auto m = motorAngles(table_, options_.max_force_n, goal[0], goal[1]);
  return {m[0], m[1]};
}

void BeltDevice::sendOutputs(SerialPort& port, std::span<const double> outputs) {
  std::vector<std::uint8_t> payload;
  for (double deg : outputs) frame::putI32(payload, static_cast<std::int32_t>(std::lround(deg * 1000.0)));
  port.write(frame::encode(belt::kSetAngles, payload));
}

std::vector<double> BeltDevice::readFeedback(SerialPort& port) {
  std::vector<double> latest;
  const std::vector<std::uint8_t> bytes = port.readAvailable(0);
  parser_.feed(bytes, [&](const frame::Frame& f) {
    if (f.type != belt::kEncoder || f.payload.size() != 10) return;
    latest = {frame::getI32(f.payload, 2) * 360.0 / options_.counts_per_rev,
              frame::getI32(f.payload, 6) * 360.0 / options_.counts_per_rev};
  });
  return latest;
}

}  // namespace onetip::devices
