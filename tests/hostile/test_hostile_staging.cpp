// A live run in another PID namespace writing the same output name is never
// harmed (issue 39 item 5): a containerised run's staging was judged by
// kill(pid, 0) from the host, where its pid means nothing, and deleted. Here
// `process --out P` runs in a new PID namespace (unshare, as root) with a pid
// that does not exist on the host; while it works, a run on the host writes
// the same P, which cleans up stale staging beside P first. The namespaced run
// must still finish and commit.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>

#include "cli_runner.hpp"
#include "core/csv_table.hpp"
#include "scratch_dir.hpp"
#include "test_paths.hpp"

namespace {

using namespace onetip;
using namespace onetip::test_support;
namespace fs = std::filesystem;

const std::string kDemo = shippedScenario("demo_touch");

TEST(HostileStaging, ALiveRunInAnotherPidNamespaceKeepsItsStaging) {
  if (std::system("unshare --pid --fork --mount-proc true >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "unshare --pid needs root or user namespaces here";
  const ScratchDir dir("onetip-hostile-ns");
  const CliRun sim = runCli("sim --quiet --frames 1 --scenario " + kDemo + " --out " + dir.file("one"), dir.file("err"));
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  const std::string rig = " --calib " + dir.file("one/calib.yaml") + " --pattern " + dir.file("one/pattern.yaml");
  const std::string pose = dir.file("pose.csv");

  // In the namespace the program gets pid 99991 (ns_last_pid), which no host process has.
  const std::string inner = "echo 99990 > /proc/sys/kernel/ns_last_pid; " + std::string(onetip::test::cliPath()) +
                            " process --quiet --input sim:" + kDemo + rig + " --out " + pose + "; exit $?";
  const std::string foreign_err = dir.file("foreign.err");
  const pid_t foreign = ::fork();
  if (foreign == 0) {
    ::execlp("unshare", "unshare", "--pid", "--fork", "--mount-proc", "sh", "-c",
             (inner + " 2>" + foreign_err).c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Once its staging exists, the host writes the same pose.csv from a one-frame folder.
  int status = 0;
  bool foreign_ended = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!anyEntryContains(dir.path(), "pose.csv.tmp.") && !foreign_ended &&
         std::chrono::steady_clock::now() < deadline) {
    foreign_ended = ::waitpid(foreign, &status, WNOHANG) == foreign;
    ::usleep(10000);
  }
  ASSERT_FALSE(foreign_ended) << "the namespaced run ended before its staging was seen: " << readText(foreign_err);
  const CliRun host = runCli("process --quiet --input " + dir.file("one/frames") + rig + " --out " + pose, dir.file("err"));
  EXPECT_EQ(host.exit_code, 0) << host.err;
  ASSERT_EQ(::waitpid(foreign, &status, 0), foreign);
  EXPECT_EQ(exitCodeOf(status), 0) << readText(foreign_err);  // without the fix: "cannot move into place"
  EXPECT_GT(readCsv(pose).rows.size(), 1u);  // the namespaced run committed last, whole
  EXPECT_FALSE(anyEntryContains(dir.path(), ".tmp."));
}

}  // namespace
