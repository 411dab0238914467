// Staging owned provably (core/staging_owner.hpp, issue 39): only staging of
// this host and boot whose lock is free (or, without a lock, whose pid is gone
// from this PID namespace) is removed; a live run's staging in another PID
// namespace (its pid means nothing here), another host's or boot's, an older
// version's and a kept recording's are never touched.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/atomic_file.hpp"
#include "core/staging_owner.hpp"
#include "scratch_dir.hpp"

namespace {

using namespace onetip;
namespace fs = std::filesystem;

// A pid that was used and whose process is gone (reaped).
long deadPid() {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  ::waitpid(pid, nullptr, 0);
  return pid;
}

std::string nameOf(const std::string& target, const char* infix, const StagingOwner& o, const char* random = "Ab12Cd") {
  return target + infix + o.host + "." + o.boot + "." + o.pidns + "." + std::to_string(o.pid) + "." + random;
}

void touch(const std::string& path) { std::ofstream(path) << "x"; }

// Holds flock on `path` as a live owner would (a descriptor of this test process).
struct HeldLock {
  int fd;
  explicit HeldLock(const std::string& path) : fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC)) {
    EXPECT_GE(fd, 0) << path;
    EXPECT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  }
  ~HeldLock() { ::close(fd); }
};

TEST(StagingOwner, NamesCarryHostBootNamespaceAndPidAndParseBack) {
  const StagingOwner self = thisStagingOwner();
  EXPECT_NE(self.boot, "unknown");  // Linux with /proc: the tests run there
  EXPECT_NE(self.pidns, "unknown");
  const auto parsed = parseStagingOwner(stagingOwnerTag() + ".Zz9yY8");
  ASSERT_TRUE(parsed);
  EXPECT_EQ(parsed->host, self.host);
  EXPECT_EQ(parsed->boot, self.boot);
  EXPECT_EQ(parsed->pidns, self.pidns);
  EXPECT_EQ(parsed->pid, static_cast<long>(::getpid()));
  for (const char* bad : {"", "123", "123.Ab12Cd", "h.0123456789abcdef.1.2.Ab12Cd~", "h.0123456789abcdef.1.2.Ab12Cd.dir",
                          "h.xyz.1.2.Ab12Cd", "h.0123456789abcdef.1.2.Ab1"})
    EXPECT_FALSE(parseStagingOwner(bad)) << bad;
}

TEST(StagingOwner, AbandonedStagingOfThisHostAndBootIsRemovedAndNothingElse) {
  const test_support::ScratchDir dir("onetip-staging");
  const std::string target = dir.file("pose.csv");
  StagingOwner dead = thisStagingOwner();
  dead.pid = deadPid();
  StagingOwner foreign_ns = thisStagingOwner();  // a container's run: its pid is not ours to judge
  foreign_ns.pidns = "1";
  foreign_ns.pid = dead.pid;
  StagingOwner other_host = dead, other_boot = dead;
  other_host.host = "elsewhere";
  other_boot.boot = "0123456789abcdef";

  const std::string killed_file = nameOf(target, ".tmp.", dead, "AAAAAA");
  const std::string killed_dir = nameOf(target, ".tmp.", dead, "BBBBBB");
  const std::string killed_early_dir = nameOf(target, ".tmp.", dead, "CCCCCC");  // killed before its lock file
  const std::string live_foreign = nameOf(target, ".tmp.", foreign_ns, "DDDDDD");
  const std::string unlocked_foreign_dir = nameOf(target, ".tmp.", foreign_ns, "EEEEEE");
  const std::string live_here_held = nameOf(target, ".tmp.", dead, "FFFFFF");  // lock held: alive whatever the pid
  const std::string remote = nameOf(target, ".tmp.", other_host);
  const std::string rebooted = nameOf(target, ".tmp.", other_boot);
  const std::string kept_recording = nameOf(target, ".partial.", dead);
  const std::string older_version = target + ".tmp." + std::to_string(dead.pid) + ".Ab12Cd";
  for (const auto& f : {killed_file, live_foreign, live_here_held, remote, rebooted, older_version}) touch(f);
  for (const auto& d : {killed_dir, killed_early_dir, unlocked_foreign_dir, kept_recording}) fs::create_directory(d);
  touch(killed_dir + "/" + kStagingLockName);
  touch(kept_recording + "/" + kStagingLockName);
  const HeldLock foreign_lock(live_foreign), here_lock(live_here_held);

  AtomicFile f(target);  // opening one cleans up beside the target
  f.stream() << "a\n";
  f.commit();
  EXPECT_FALSE(fs::exists(killed_file));
  EXPECT_FALSE(fs::exists(killed_dir));
  EXPECT_FALSE(fs::exists(killed_early_dir));  // no lock, but its pid is gone from this namespace
  EXPECT_TRUE(fs::exists(live_foreign));
  EXPECT_TRUE(fs::exists(unlocked_foreign_dir));  // no lock yet, and a foreign pid proves nothing
  EXPECT_TRUE(fs::exists(live_here_held));
  EXPECT_TRUE(fs::exists(remote));
  EXPECT_TRUE(fs::exists(rebooted));
  EXPECT_TRUE(fs::exists(kept_recording));
  EXPECT_TRUE(fs::exists(older_version));
  EXPECT_EQ(abandonedStaging(target, true), std::vector<std::string>{kept_recording});
}

TEST(StagingOwner, ALiveWritersStagingIsLockedAndALiveFolderKeepsItsLockFile) {
  const test_support::ScratchDir dir("onetip-staging");
  const std::string target = dir.file("out.csv");
  AtomicFile live(target);
  AtomicDir live_dir(dir.file("out"));
  for (const auto& e : fs::directory_iterator(dir.path())) {
    const std::string name = e.path().filename().string();
    const std::string infix = name.rfind("out.csv.tmp.", 0) == 0 ? "out.csv.tmp." : "out.tmp.";
    const auto owner = parseStagingOwner(name.substr(infix.size()));
    ASSERT_TRUE(owner) << name;
    EXPECT_FALSE(stagingAbandoned(e.path(), *owner)) << name;
  }
  EXPECT_TRUE(fs::exists(fs::path(live_dir.path()) / kStagingLockName));
  removeStaleStaging(target);
  removeStaleStaging(dir.file("out"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 2);
  live_dir.commit();
  EXPECT_FALSE(fs::exists(dir.path() / "out" / kStagingLockName));  // not left in the output
}

}  // namespace
