// tools/interrupt.hpp — SIGINT/SIGTERM for the commands that write files.
//
// While an InterruptHandlers object lives, SIGINT and SIGTERM only set a flag
// (async-signal-safe: a lock-free atomic store); the command polls it between
// frames or rows, stops, and either commits complete outputs of the work done
// so far or unwinds so its staging files are removed (core/atomic_file.hpp).
// The previous handlers come back when the object is destroyed. A command that
// stopped this way exits with status 130 (128 + SIGINT, as shells report it).
#pragma once

#include <atomic>
#include <csignal>

namespace onetip::tools {

class InterruptHandlers {
 public:
  InterruptHandlers();  // clears the flag, installs the handlers
  ~InterruptHandlers();
  InterruptHandlers(const InterruptHandlers&) = delete;
  InterruptHandlers& operator=(const InterruptHandlers&) = delete;

 private:
  struct sigaction old_int_ {}, old_term_ {};
};

// True once SIGINT or SIGTERM arrived while handlers were installed.
bool interruptRequested() noexcept;
// The flag itself, for loops that take a stop flag (calib::collectDataset).
const std::atomic<bool>* interruptFlag() noexcept;

constexpr int kInterruptedExit = 130;

}  // namespace onetip::tools
