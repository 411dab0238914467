// `onetip spnav` end to end: the command serves the simulated sensor and the
// real libspnav client (Debian's, via SPNAV_SOCKET) receives motion events
// whose six values equal the pipeline's own 6-D input events (public C++ API,
// same scenario) scaled as docs/os_outputs.md documents (onetip::spnavAxes),
// then the explicit zero at contact end; SIGTERM stops it cleanly.
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <spnav.h>
#include <sys/socket.h>
#include <sys/wait.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <thread>

#include "onetip/onetip.hpp"
#include "test_paths.hpp"

extern char** environ;

namespace onetip {
namespace {

const std::string kScenario = std::string(onetip::test::sourceDir()) + "/samples/scenarios/press.yaml";
using Axes = std::array<std::int32_t, 6>;

std::string tempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("onetip_spnavcmd_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

// Runs `onetip ARGS...` in the background.
pid_t spawnCli(const std::vector<std::string>& args) {
  std::vector<std::string> all{onetip::test::cliPath()};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  EXPECT_EQ(posix_spawn(&pid, onetip::test::cliPath(), nullptr, nullptr, argv.data(), environ), 0);
  return pid;
}

int waitExit(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

bool connectLibspnav(const std::string& socket, double timeout_s) {
  ::setenv("SPNAV_SOCKET", socket.c_str(), 1);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < deadline) {
    if (std::filesystem::exists(socket) && spnav_open() == 0) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

// Motion events until the server closes the connection (or timeout_s passes quietly).
std::vector<Axes> readMotions(double timeout_s) {
  std::vector<Axes> out;
  for (;;) {
    pollfd p{spnav_fd(), POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(timeout_s * 1000)) <= 0) break;
    spnav_event ev;
    const int got = spnav_poll_event(&ev);
    if (got == 0) {
      if (p.revents & (POLLHUP | POLLERR)) break;
      char probe;
      if (::recv(spnav_fd(), &probe, 1, MSG_PEEK | MSG_DONTWAIT) == 0) break;  // closed by the server
      continue;
    }
    if (ev.type == SPNAV_EVENT_MOTION)
      out.push_back({ev.motion.x, ev.motion.y, ev.motion.z, ev.motion.rx, ev.motion.ry, ev.motion.rz});
  }
  return out;
}

// What the server must send for the pipeline's events (docs/os_outputs.md):
// every input event scaled, all-zero motions only once in a row, an explicit
// zero at each contact end.
std::vector<Axes> expectedMotions() {
  SensorOptions o;
  o.lossless = true;
  o.event_queue_capacity = 100000;
  Sensor sensor(onetip::SensorConfig("sim:" + kScenario, "", "", ""), o);
  sensor.start();
  EXPECT_TRUE(sensor.waitFinished(240));
  std::vector<Axes> out;
  bool last_zero = true;
  Event e;
  while (sensor.pollEvent(e)) {
    if (e.type != EventType::input && e.type != EventType::contact_end) continue;
    const Axes a = e.type == EventType::input ? spnavAxes(e.input) : Axes{};
    const bool zero = std::all_of(a.begin(), a.end(), [](std::int32_t v) { return v == 0; });
    if (zero && e.type == EventType::input && last_zero) continue;
    last_zero = zero;
    out.push_back(a);
  }
  return out;
}

TEST(SpnavCommand, LibspnavReceivesThePipelinesInputScaledAsDocumented) {
  const std::string options = tempPath("lossless.yaml");
  std::ofstream(options) << "%YAML:1.0\nlossless: 1\n";
  const std::string socket = tempPath("spnav.sock");
  const pid_t pid = spawnCli({"spnav", "--input", "sim:" + kScenario, "--socket", socket, "--options", options,
                              "--wait-client", "60"});
  ASSERT_TRUE(connectLibspnav(socket, 20)) << "no server at " << socket;
  const std::vector<Axes> got = readMotions(60);
  spnav_close();
  EXPECT_EQ(waitExit(pid), 0);  // the source ended
  EXPECT_FALSE(std::filesystem::exists(socket));
  std::filesystem::remove(options);

  const std::vector<Axes> expected = expectedMotions();
  ASSERT_GT(expected.size(), 20u);
  EXPECT_EQ(got, expected);
  EXPECT_EQ(got.back(), Axes{});  // the explicit zero at contact end
  const auto deepest = std::max_element(got.begin(), got.end(), [](const Axes& a, const Axes& b) { return a[2] < b[2]; });
  EXPECT_GT((*deepest)[2], 200);  // a ~3 mm press reaches most of the 350-unit full scale
}

TEST(SpnavCommand, SigtermStopsItCleanly) {
  const std::string options = tempPath("realtime.yaml");
  std::ofstream(options) << "%YAML:1.0\nplayback_rate: 0.2\n";  // the 3 s scenario would take 15 s
  const std::string socket = tempPath("spnav_term.sock");
  const pid_t pid = spawnCli({"spnav", "--input", "sim:" + kScenario, "--socket", socket, "--options", options});
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (!std::filesystem::exists(socket) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_TRUE(std::filesystem::exists(socket));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  const auto t0 = std::chrono::steady_clock::now();
  ::kill(pid, SIGTERM);
  EXPECT_EQ(waitExit(pid), 130);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5.0);
  EXPECT_FALSE(std::filesystem::exists(socket));  // the server removed its socket
  std::filesystem::remove(options);
}

TEST(JoystickCommand, WithoutUinputItNamesTheDeviceAndFails) {
  const pid_t pid = spawnCli({"joystick", "--input", "sim:" + kScenario, "--uinput", "/nonexistent/uinput"});
  EXPECT_EQ(waitExit(pid), 2);
}

}  // namespace
}  // namespace onetip
