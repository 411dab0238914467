// Fuzzes the simulator's scenario loader (sim/scenario.hpp): a scenario that
// loads, or InputError.
#include "core/error.hpp"
#include "fuzz_input_file.hpp"
#include "sim/scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    onetip::sim::loadScenario(onetip::fuzz::writeConfigFile(data, size));
  } catch (const onetip::InputError&) {
  }
  return 0;
}
