// Fuzzes the calibration loader (core/calibration.hpp) through its public
// function: a file either loads into a calibration that validates, or is
// refused with an InputError; any other exception or a crash is a finding.
#include "core/calibration.hpp"
#include "core/error.hpp"
#include "fuzz_input_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    onetip::loadCalibration(onetip::fuzz::writeConfigFile(data, size)).validate();
  } catch (const onetip::InputError&) {
  }
  return 0;
}
