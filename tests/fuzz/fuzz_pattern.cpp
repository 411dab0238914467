// Fuzzes the marker-pattern loader (core/pattern.hpp): loads and validates, or InputError.
#include "core/error.hpp"
#include "core/pattern.hpp"
#include "fuzz_input_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    onetip::loadPattern(onetip::fuzz::writeConfigFile(data, size)).validate();
  } catch (const onetip::InputError&) {
  }
  return 0;
}
