// tests/dds/scoped_env.hpp — one environment variable set (or unset) for the
// life of the object and restored after it, pass or fail: the DDS tests give
// an in-process participant a CYCLONEDDS_URI this way.
#pragma once

#include <cstdlib>
#include <optional>
#include <string>

namespace onetip::test_support {

class ScopedEnv {
 public:
  // value nullopt: unset the variable.
  ScopedEnv(std::string name, const std::optional<std::string>& value) : name_(std::move(name)) {
    if (const char* old = std::getenv(name_.c_str())) old_ = old;
    if (value) ::setenv(name_.c_str(), value->c_str(), 1);
    else ::unsetenv(name_.c_str());
  }
  ~ScopedEnv() {
    if (old_) ::setenv(name_.c_str(), old_->c_str(), 1);
    else ::unsetenv(name_.c_str());
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  std::string name_;
  std::optional<std::string> old_;
};

}  // namespace onetip::test_support
