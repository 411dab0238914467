// tests/hostile/cli_runner.hpp — runs the `onetip` program as a child process
// for the hostile-input tests: its exit status and stderr, optionally
// signalled once a file appears (to interrupt it mid-run).
#pragma once

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>
#include "test_paths.hpp"

namespace onetip::test_support {

// A shipped touch scenario of the checkout, samples/scenarios/<name>.yaml, absolute.
inline std::string shippedScenario(const std::string& name) {
  return (std::filesystem::path(onetip::test::sourceDir()) / "samples/scenarios" / (name + ".yaml")).string();
}

struct CliRun {
  int exit_code = -1;    // the exit status, or 128 + signal when it was killed by one
  std::string err;       // what it wrote to stderr
  bool signalled = false;  // the signal was sent (the condition was met in time)
};

inline std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline int exitCodeOf(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status); }

// Runs `onetip::test::cliPath() args` through /bin/sh (stdout discarded, stderr to err_file).
// When `signal_when` is given, polls it every 20 ms and sends `sig` once it
// returns true (then waits); gives up on signalling after 60 s. `in_child`
// runs in the child before the program starts (e.g. to lower a limit).
inline CliRun runCli(const std::string& args, const std::string& err_file,
                     const std::function<bool()>& signal_when = {}, int sig = SIGINT,
                     const std::function<void()>& in_child = {}) {
  CliRun r;
  const std::string cmd = std::string("exec ") + onetip::test::cliPath() + " " + args + " >/dev/null 2>" + err_file;
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (in_child) in_child();
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  if (signal_when) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < deadline) {
      int status = 0;
      if (::waitpid(pid, &status, WNOHANG) == pid) {  // ended before the condition
        r.exit_code = exitCodeOf(status);
        r.err = readText(err_file);
        return r;
      }
      if (signal_when()) {
        ::kill(pid, sig);
        r.signalled = true;
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  r.exit_code = exitCodeOf(status);
  r.err = readText(err_file);
  return r;
}

// Runs `onetip::test::cliPath() args` to the end, its stdout to out_file and stderr to err_file.
inline CliRun runCliWithOutput(const std::string& args, const std::string& out_file, const std::string& err_file) {
  CliRun r;
  const std::string cmd =
      std::string("exec ") + onetip::test::cliPath() + " " + args + " >" + out_file + " 2>" + err_file;
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  r.exit_code = exitCodeOf(status);
  r.err = readText(err_file);
  return r;
}

// A refusal as the command-line contract wants it: exit status 2 and one line on stderr that mentions `mentions`.
inline void expectRefused(const CliRun& r, const std::string& mentions) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(mentions), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
}

// For runCli's in_child: a full disk, as a file-size limit (writes past it fail with EFBIG; SIGXFSZ ignored).
inline std::function<void()> fileSizeLimit(rlim_t bytes) {
  return [bytes] {
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{bytes, bytes};
    ::setrlimit(RLIMIT_FSIZE, &limit);
  };
}

// True when some entry of `dir` has a name containing `part`.
inline bool anyEntryContains(const std::filesystem::path& dir, const std::string& part) {
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec))
    if (e.path().filename().string().find(part) != std::string::npos) return true;
  return false;
}

}  // namespace onetip::test_support
