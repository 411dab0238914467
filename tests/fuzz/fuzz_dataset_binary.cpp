// Fuzzes the binary dataset reader (haptics/dataset_binary.hpp): a dataset
// whose every value is finite, or InputError.
#include <cmath>

#include "core/error.hpp"
#include "fuzz_input_file.hpp"
#include "haptics/dataset_binary.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const auto d = onetip::haptics::readDatasetBinary(onetip::fuzz::writeInputFile(data, size, ".bin"));
    for (float v : d.commands)
      if (!std::isfinite(v)) __builtin_trap();
    for (float v : d.sensed)
      if (!std::isfinite(v)) __builtin_trap();
  } catch (const onetip::InputError&) {
  }
  return 0;
}
