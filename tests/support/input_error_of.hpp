// tests/support/input_error_of.hpp — the message of the onetip::InputError a
// call throws, or "" when it throws none (other exceptions pass through), for
// tests that check bad input is refused with a message naming what is wrong.
#pragma once

#include <functional>
#include <string>

#include "core/error.hpp"

namespace onetip::test_support {

inline std::string inputErrorOf(const std::function<void()>& call) {
  try {
    call();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace onetip::test_support
