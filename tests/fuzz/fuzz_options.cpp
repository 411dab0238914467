// Fuzzes the options file through the public onetip::SensorOptions::load
// (pipeline/options_io.cpp over core/config_file.hpp: YAML or JSON). A file
// either loads or is refused with Error(ErrorKind::input); any other error or a
// crash is a finding. What loads must keep the documented contract: it
// validates, and save() then load() gives the same options (every value
// written exactly).
#include <cstdio>
#include <cstdlib>

#include "fuzz_input_file.hpp"
#include "onetip/error.hpp"
#include "onetip/sensor_options.hpp"

namespace {

[[noreturn]] void violated(const char* what) {
  std::fprintf(stderr, "fuzz_options: contract violated: %s\n", what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  onetip::SensorOptions loaded;
  try {
    loaded = onetip::SensorOptions::load(onetip::fuzz::writeConfigFile(data, size));
  } catch (const onetip::Error& e) {
    if (e.kind() != onetip::ErrorKind::input) violated(e.what());
    return 0;
  }
  try {
    loaded.validate();
  } catch (const onetip::Error& e) {
    violated(e.what());  // load() accepted options that validate() refuses
  }
  const std::string saved = onetip::fuzz::scratchPath(".saved.yaml");
  try {
    loaded.save(saved);
    if (!(onetip::SensorOptions::load(saved) == loaded)) violated("save() then load() changed a value");
  } catch (const onetip::Error& e) {
    violated(e.what());  // saving or reloading valid options failed
  }
  return 0;
}
