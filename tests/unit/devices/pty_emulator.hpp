// tests/unit/devices/pty_emulator.hpp — a device's firmware, emulated on the
// master side of a pseudo-terminal, for driving the real serial drivers end
// to end.
//
// The driver opens path(), a symlink to the pty's slave (like a udev
// /dev/serial/by-id link). hangUp() closes the pty (the driver then sees EIO /
// hang-up) and removes the link; recreate() makes a new pty behind the same
// path. A thread reads the master and hands every byte to onBytes(), with the
// steady_clock time it was read; reply() writes to the master.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <span>
#include <string>
#include <thread>
#include <vector>

namespace onetip::devices::testing {

using Clock = std::chrono::steady_clock;

class PtyEmulator {
 public:
  PtyEmulator();
  virtual ~PtyEmulator();
  PtyEmulator(const PtyEmulator&) = delete;
  PtyEmulator& operator=(const PtyEmulator&) = delete;

  const std::string& path() const { return link_; }
  void hangUp();
  void recreate();
  // Protocol violations seen so far (empty when every byte followed the protocol).
  std::vector<std::string> violations() const;

 protected:
  // Must be called by the derived constructor (the thread calls onBytes).
  void start();
  // Must be called by the derived destructor.
  void stop();
  virtual void onBytes(std::span<const std::uint8_t> bytes, Clock::time_point t) = 0;
  // Periodic call from the emulator thread (e.g. to stream feedback), every ~1 ms.
  virtual void onIdle(Clock::time_point) {}
  void reply(std::span<const std::uint8_t> bytes);
  void violation(const std::string& what);
  mutable std::mutex mutex_;  // guards the derived class's recorded state too

 private:
  void openPty();
  void closePty();
  void run();
  std::string dir_, link_;
  int master_ = -1, slave_ = -1;
  std::thread thread_;
  std::atomic<bool> running_{false};
  std::vector<std::string> violations_;
};

// Waits until pred(emulator.events()) holds or timeout_s passes; returns whether it held.
template <class Emulator, class Pred>
bool waitFor(const Emulator& emulator, Pred pred, double timeout_s) {
  const auto end = Clock::now() + std::chrono::duration<double>(timeout_s);
  while (Clock::now() < end) {
    if (pred(emulator.events())) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return pred(emulator.events());
}

}  // namespace onetip::devices::testing
