// tests/fuzz/fuzz_input_file.hpp — the fuzzer's bytes as a file, for loaders
// that take a path (calibration, pattern, options, scenario, datasets).
//
// One file per process under the temp folder, rewritten for every input and
// removed at exit. Its extension picks the format where the loader looks at
// it (".yaml" or ".json"), so both parsers are reached from one corpus: the
// first byte's low bit chooses, and the rest of the input is the file.
// scratchPath() names further per-process files (a harness's own output).
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace onetip::fuzz {

// The file <temp>/onetip-fuzz-<pid><extension>, removed at exit; extension is
// one of ".yaml", ".json", ".csv", ".bin", ".saved.yaml".
inline std::string scratchPath(const std::string& extension) {
  static const std::string stem =
      (std::filesystem::temp_directory_path() / ("onetip-fuzz-" + std::to_string(::getpid()))).string();
  static const bool registered = [] {
    std::atexit([] {
      for (const char* ext : {".yaml", ".json", ".csv", ".bin", ".saved.yaml"}) std::remove((stem + ext).c_str());
    });
    return true;
  }();
  (void)registered;
  return stem + extension;
}

inline std::string writeInputFile(const std::uint8_t* data, std::size_t size, const std::string& extension) {
  const std::string path = scratchPath(extension);
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data),
                                                               static_cast<std::streamsize>(size));
  return path;
}

// ".yaml" or ".json" from the first byte, and the file from the rest.
inline std::string writeConfigFile(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return writeInputFile(data, 0, ".yaml");
  return writeInputFile(data + 1, size - 1, (data[0] & 1) ? ".json" : ".yaml");
}

}  // namespace onetip::fuzz
