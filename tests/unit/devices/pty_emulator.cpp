#include "pty_emulator.hpp"

#include <poll.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace onetip::devices::testing {

PtyEmulator::PtyEmulator() {
  char tmpl[] = "/tmp/onetip-pty-XXXXXX";
  if (!::mkdtemp(tmpl)) throw std::runtime_error("mkdtemp failed");
  dir_ = tmpl;
  link_ = dir_ + "/tty";
  openPty();
}

PtyEmulator::~PtyEmulator() {
  stop();
  closePty();
  std::filesystem::remove_all(dir_);
}

void PtyEmulator::openPty() {
  termios raw{};
  ::cfmakeraw(&raw);
  char name[256];
  if (::openpty(&master_, &slave_, name, &raw, nullptr) != 0) throw std::runtime_error("openpty failed");
  std::filesystem::remove(link_);
  std::filesystem::create_symlink(name, link_);
}

void PtyEmulator::closePty() {
  if (master_ >= 0) ::close(master_);
  if (slave_ >= 0) ::close(slave_);
  master_ = slave_ = -1;
  std::filesystem::remove(link_);
}

void PtyEmulator::start() {
  running_ = true;
  thread_ = std::thread([this] { run(); });
}

void PtyEmulator::stop() {
  running_ = false;
  if (thread_.joinable()) thread_.join();
}

void PtyEmulator::hangUp() {
  stop();
  closePty();
}

void PtyEmulator::recreate() {
  openPty();
  start();
}

void PtyEmulator::run() {
  std::uint8_t buf[512];
  while (running_) {
    pollfd p{master_, POLLIN, 0};
    if (::poll(&p, 1, 1) > 0 && (p.revents & POLLIN)) {
      const ssize_t n = ::read(master_, buf, sizeof buf);
      if (n > 0) onBytes(std::span<const std::uint8_t>(buf, static_cast<size_t>(n)), Clock::now());
    }
    onIdle(Clock::now());
  }
}

void PtyEmulator::reply(std::span<const std::uint8_t> bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(master_, bytes.data() + done, bytes.size() - done);
    if (n <= 0) return;
    done += static_cast<size_t>(n);
  }
}

void PtyEmulator::violation(const std::string& what) {
  // called from onBytes with mutex_ held by the derived class or not: keep a separate list
  violations_.push_back(what);
}

std::vector<std::string> PtyEmulator::violations() const {
  std::lock_guard lock(mutex_);
  return violations_;
}

}  // namespace onetip::devices::testing
