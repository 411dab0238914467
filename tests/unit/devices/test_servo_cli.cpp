// `onetip servo` end to end: the CLI against the Maestro emulator on a pty.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>

#include "maestro_emulator.hpp"
#include "test_paths.hpp"

namespace onetip::devices {
namespace {

struct CliRun {
  int status;
  std::string output;
};

CliRun runCli(const std::string& args) {
  CliRun r{0, {}};
  FILE* p = ::popen((std::string(onetip::test::cliPath()) + " servo " + args + " 2>&1").c_str(), "r");
  std::array<char, 256> buf{};
  while (std::fgets(buf.data(), buf.size(), p)) r.output += buf.data();
  r.status = ::pclose(p);
  return r;
}

TEST(ServoCli, SendsOneClampedTargetPerServoThenExits) {
  testing::MaestroEmulator emu;
  const CliRun r = runCli("--port " + emu.path() + " --angles 10,100.5,400 --channels 2,3,4");
  ASSERT_EQ(r.status, 0) << r.output;
  ASSERT_TRUE(testing::waitFor(emu, [](const auto& ev) { return ev.size() >= 9; }, 2.0));
  const auto targets = emu.events(0x84);
  ASSERT_EQ(targets.size(), 3u);
  const int expected[3] = {4 * (600 + 300), 4 * (600 + 1005), 4 * (600 + 1950)};  // 30, 100.5, 195 deg
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(targets[i].channel, 2 + i);
    EXPECT_EQ(targets[i].value, expected[i]);
  }
  EXPECT_EQ(emu.events(0x87).size(), 3u);
  EXPECT_TRUE(emu.violations().empty());
}

TEST(ServoCli, BadPortOrAnglesGiveOneLineAndNonZeroExit) {
  for (const std::string args : {"--port /dev/onetip-missing --angles 40,50,60", "--port /dev/null --angles 40,50,60",
                                 "--port /dev/null --angles 40,50", "--port /dev/null --angles 40,x,60",
                                 "--port /dev/null --angles 40,nan,60", "--angles 40,50,60",
                                 "--port /dev/null --angles 40,50,60 --channels 0,0,1"}) {
    const CliRun r = runCli(args);
    EXPECT_NE(r.status, 0) << args;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << args << ": " << r.output;
  }
}

}  // namespace
}  // namespace onetip::devices
