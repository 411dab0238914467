// Fuzzes the queries CSV reader (haptics/tactile_dataset.hpp): finite values, or InputError.
#include <cmath>

#include "core/error.hpp"
#include "fuzz_input_file.hpp"
#include "haptics/tactile_dataset.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const auto q = onetip::haptics::readQueriesCsv(onetip::fuzz::writeInputFile(data, size, ".csv"));
    for (double v : q.values)
      if (!std::isfinite(v)) __builtin_trap();
  } catch (const onetip::InputError&) {
  }
  return 0;
}
