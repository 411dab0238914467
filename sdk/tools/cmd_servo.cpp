// `onetip servo --port TTY --angles A1,A2,A3 [--channels 0,1,2] [--baud B]`
// (docs/reference.md): one target per servo to a Pololu Maestro (compact
// protocol), clamped to the platform's safe range [30, 195] deg, then exit.
#include <iostream>
#include <sstream>

#include "command.hpp"
#include "core/csv_table.hpp"
#include "core/error.hpp"
#include "devices/servo_platform.hpp"

namespace onetip::tools {
namespace {

std::array<double, 3> parseTriple(const std::string& text, const std::string& option) {
  std::array<double, 3> values{};
  std::stringstream in(text);
  std::string cell;
  size_t n = 0;
  while (std::getline(in, cell, ',')) {
    if (n < 3) values[n] = parseNumber(cell, "option '--" + option + "' value " + std::to_string(n + 1));
    ++n;  // every cell counts: a fourth value is an error, never silently dropped
  }
  if (n != 3 || text.empty() || text.back() == ',')
    throw InputError("option '--" + option + "': needs exactly three comma-separated numbers, got '" + text + "'");
  return values;
}

int runServo(const Args& args) {
  devices::ServoPlatformOptions options;
  options.serial.port = args.get("port");
  options.serial.baud = args.getInt("baud", options.serial.baud);
  const std::array<double, 3> angles = parseTriple(args.get("angles"), "angles");
  if (const auto channels = args.optional("channels")) {
    const std::array<double, 3> c = parseTriple(*channels, "channels");
    for (int i = 0; i < 3; ++i) {
      if (c[i] != static_cast<int>(c[i])) throw InputError("option '--channels': channels must be whole numbers");
      options.channels[i] = static_cast<int>(c[i]);
    }
  }
  const std::array<double, 3> sent = devices::sendServoTargetsOnce(options, angles);
  std::cout << "sent " << formatNumber(sent[0], 3) << "," << formatNumber(sent[1], 3) << ","
            << formatNumber(sent[2], 3) << " deg to channels " << options.channels[0] << "," << options.channels[1]
            << "," << options.channels[2] << " on " << options.serial.port << std::endl;
  return 0;
}

const CommandRegistrar kServo{Command{
    "servo",
    "send one target per servo of the 3-servo cable platform to a Pololu Maestro, clamped to [30, 195] deg",
    {{"port", "serial port of the Maestro (e.g. /dev/ttyACM0)", false, true},
     {"angles", "A1,A2,A3: servo angles in degrees (m1 front, m2 rear right, m3 rear left)", false, true},
     {"channels", "Maestro channels of m1,m2,m3 (default 0,1,2)", false, false},
     {"baud", "baud rate (default 115200)", false, false}},
    runServo}};

}  // namespace
}  // namespace onetip::tools
