// tests/dds/child_process.hpp — one program run as a child process for the
// DDS tests (publisher, subscriber, operator), through /bin/sh so it can be
// prefixed with `ip netns exec NS`, stdout and stderr to a log file; or a
// function run in a forked copy of the test (call it before the test starts
// threads or DDS). A child still running when the object goes out of scope is
// killed (SIGKILL) and reaped.
#pragma once

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>

namespace onetip::test_support {

class ChildProcess {
 public:
  ChildProcess(const std::string& command, const std::string& log_file) : log_(log_file) {
    const std::string cmd = "exec " + command + " >" + log_file + " 2>&1";
    pid_ = ::fork();
    if (pid_ == 0) {
      ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
  }
  // Runs body() in a forked child, which exits with its result (no log).
  explicit ChildProcess(const std::function<int()>& body) {
    pid_ = ::fork();
    if (pid_ == 0) {
      try {
        ::_exit(body());
      } catch (...) {
        ::_exit(126);
      }
    }
  }
  ~ChildProcess() { kill(); }
  // Ends the child at once, without a word to anyone (SIGKILL), and reaps it.
  void kill() {
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
      pid_ = -1;
    }
  }
  // Sends a signal (e.g. SIGINT: `onetip teleop` stops and prints its summary).
  void signal(int sig) {
    if (pid_ > 0) ::kill(pid_, sig);
  }
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  // The exit status, or -1 when it had not ended after timeout_s (it is then killed).
  int wait(double timeout_s) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    while (pid_ > 0) {
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      }
      if (std::chrono::steady_clock::now() > deadline) {
        kill();
        return -1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return -1;
  }
  std::string log() const {
    if (log_.empty()) return {};
    std::ifstream in(log_);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }

 private:
  pid_t pid_ = -1;
  std::string log_;
};

}  // namespace onetip::test_support
