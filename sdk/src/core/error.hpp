// core/error.hpp — the SDK's error type for bad input.
//
// Code that reads user input (files, options, command lines, frames) throws
// InputError with a one-line message that names what is wrong, e.g.
// "scenario.yaml: keyframes[2].t: must be greater than the previous keyframe's t".
// The command-line tool prints it and exits non-zero; the C ABI turns it into an
// error code. Programming errors stay assertions, never InputError.
#pragma once

#include <stdexcept>
#include <string>

namespace onetip {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace onetip
