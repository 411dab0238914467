// tests/support/scratch_dir.hpp — a private directory for one test's files,
// created fresh under the system temp directory (mkdtemp, so parallel test
// processes never share one) and removed with everything in it when the
// object goes out of scope, pass or fail.
#pragma once

#include <stdlib.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace onetip::test_support {

class ScratchDir {
 public:
  explicit ScratchDir(const std::string& prefix = "onetip-test") {
    std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "-XXXXXX")).string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("ScratchDir: mkdtemp failed for " + pattern);
    path_ = pattern;
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const noexcept { return path_; }
  // path() / name, as a string (for APIs and command lines taking one).
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace onetip::test_support
