// The `onetip` command-line program: `onetip <subcommand> [options]`;
// `onetip help [COMMAND]` and `onetip --version` (the SDK version).
// Every subcommand prints a one-line error naming the bad input and exits
// with status 2 when its input is missing, malformed or inconsistent.
#include <iostream>

#include "command.hpp"
#include "core/error.hpp"
#include "onetip/version.hpp"
#include "sim/sim_frame_source.hpp"

namespace {
void printCommands(const std::map<std::string, onetip::tools::Command>& registry) {
  std::cout << "usage: onetip <command> [options]   (onetip help <command>, onetip --version)\n\ncommands:\n";
  for (const auto& [name, c] : registry) std::cout << "  " << name << "  " << c.summary << "\n";
}
}  // namespace

int main(int argc, char** argv) {
  using namespace onetip::tools;
  onetip::sim::registerSimFrameSource();  // "sim:SCENARIO.yaml" is a frame source everywhere
  auto& registry = commandRegistry();
  const std::string first = argc < 2 ? "" : argv[1];
  if (first == "--version" || first == "-V") {
    std::cout << "onetip " << ONETIP_VERSION_MAJOR << "." << ONETIP_VERSION_MINOR << "." << ONETIP_VERSION_PATCH
              << "\n";
    return 0;
  }
  if (first.empty() || first == "--help" || first == "-h" || (first == "help" && argc == 2)) {
    printCommands(registry);
    return first.empty() ? 2 : 0;
  }
  const std::string name = first == "help" ? argv[2] : first;
  auto it = registry.find(name);
  if (it == registry.end()) {
    std::cerr << "onetip: unknown command '" << name << "' (see onetip help)\n";
    return 2;
  }
  if (first == "help") {
    std::cout << usageOf(it->second);
    return 0;
  }
  std::vector<std::string> rest(argv + 2, argv + argc);
  for (const auto& a : rest)
    if (a == "--help" || a == "-h") {
      std::cout << usageOf(it->second);
      return 0;
    }
  try {
    return it->second.run(Args(it->second.options, rest));
  } catch (const onetip::InputError& e) {
    std::cerr << "onetip " << it->first << ": " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "onetip " << it->first << ": internal error: " << e.what() << "\n";
    return 3;
  }
}
