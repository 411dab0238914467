// tools/frame_tally.hpp — one rule for every command that runs a frame source
// (process, spnav, joystick, publish): when more than half of the frames the
// source offered were unreadable (skipped by the source, or source errors),
// the run did not do what was asked, even though the source "ended" (issue 39:
// a folder source out of file descriptors skipped 3,394 of 3,600 frames and
// exited 0). The outputs of the readable frames are kept; the exit status is 1.
#pragma once

#include <cstdio>

namespace onetip::tools {

inline constexpr int kMostlyUnreadableExit = 1;

// Prints "<command>: N of M frames were unreadable; ..." to stderr and returns
// kMostlyUnreadableExit when unreadable > offered / 2; otherwise returns 0.
inline int unreadableFramesExit(const char* command, long long unreadable, long long offered) {
  if (offered <= 0 || 2 * unreadable <= offered) return 0;
  std::fprintf(stderr, "%s: %lld of %lld frames were unreadable (see the messages above); exit status %d\n", command,
               unreadable, offered, kMostlyUnreadableExit);
  return kMostlyUnreadableExit;
}

}  // namespace onetip::tools
