// Fuzzes the haptic dataset CSV reader (haptics/tactile_dataset.hpp): a
// dataset whose every value is finite, or InputError.
#include <cmath>

#include "core/error.hpp"
#include "fuzz_input_file.hpp"
#include "haptics/tactile_dataset.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const auto d = onetip::haptics::readDatasetCsv(onetip::fuzz::writeInputFile(data, size, ".csv"));
    for (float v : d.sensed)
      if (!std::isfinite(v)) __builtin_trap();
  } catch (const onetip::InputError&) {
  }
  return 0;
}
