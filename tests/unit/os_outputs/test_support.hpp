// Helpers shared by the os_outputs tests: the scratch directory of
// tests/support, and pipeline events built in one line.
#pragma once

#include "input/input_event.hpp"
#include "scratch_dir.hpp"

namespace onetip::os_outputs::testing {

using onetip::test_support::ScratchDir;

inline input::InputEvent makeEvent(input::EventType type, double t = 0, Input6 in = {}) {
  input::InputEvent e;
  e.type = type;
  e.t = t;
  e.input = in;
  return e;
}

}  // namespace onetip::os_outputs::testing
