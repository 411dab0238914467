// Helpers shared by the os_outputs tests: a scratch directory removed at the
// end of the test, and pipeline events built in one line.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "input/input_event.hpp"

namespace onetip::os_outputs::testing {

class ScratchDir {
 public:
  ScratchDir() {
    std::string templ = (std::filesystem::temp_directory_path() / "onetip-os-outputs-XXXXXX").string();
    if (::mkdtemp(templ.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    path_ = templ;
  }
  ~ScratchDir() { std::filesystem::remove_all(path_); }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

inline input::InputEvent makeEvent(input::EventType type, double t = 0, Input6 in = {}) {
  input::InputEvent e;
  e.type = type;
  e.t = t;
  e.input = in;
  return e;
}

}  // namespace onetip::os_outputs::testing
