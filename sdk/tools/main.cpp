// The `onetip` command-line program: `onetip <subcommand> [options]`.
// Every subcommand prints a one-line error naming the bad input and exits
// with status 2 when its input is missing, malformed or inconsistent.
#include <iostream>

#include "command.hpp"
#include "core/error.hpp"
#include "sim/sim_frame_source.hpp"

int main(int argc, char** argv) {
  using namespace onetip::tools;
  onetip::sim::registerSimFrameSource();  // "sim:SCENARIO.yaml" is a frame source everywhere
  auto& registry = commandRegistry();
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    std::cout << "usage: onetip <command> [options]   (onetip <command> --help)\n\ncommands:\n";
    for (const auto& [name, c] : registry) std::cout << "  " << name << "  " << c.summary << "\n";
    return argc < 2 ? 2 : 0;
  }
  auto it = registry.find(argv[1]);
  if (it == registry.end()) {
    std::cerr << "onetip: unknown command '" << argv[1] << "' (see onetip --help)\n";
    return 2;
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
