// AtomicFile against hostile targets (core/atomic_file.hpp): a device, a
// folder or a FIFO is refused; a planted symlink at the old staging name, or
// as the target, never gets its pointee written. (Which staging of killed runs
// is removed: test_staging_owner.cpp.)
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "input_error_of.hpp"
#include "scratch_dir.hpp"

namespace {

using namespace onetip;
using test_support::inputErrorOf;
namespace fs = std::filesystem;

std::string readAll(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeAtomically(const std::string& path, const std::string& text) {
  AtomicFile f(path);
  f.stream() << text;
  f.commit();
}

TEST(AtomicFile, RefusesDevicesFoldersAndFifos) {
  const test_support::ScratchDir dir("onetip-atomic");
  EXPECT_NE(inputErrorOf([] { AtomicFile f("/dev/null"); }).find("not a regular file"), std::string::npos);
  struct stat st {};
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));  // still the device
  EXPECT_NE(inputErrorOf([&] { AtomicFile f(dir.path().string()); }).find("not a regular file"), std::string::npos);
  ASSERT_EQ(::mkfifo(dir.file("fifo").c_str(), 0600), 0);
  EXPECT_NE(inputErrorOf([&] { AtomicFile f(dir.file("fifo")); }).find("not a regular file"), std::string::npos);
  fs::create_symlink("/dev/null", dir.path() / "to_null");
  EXPECT_NE(inputErrorOf([&] { AtomicFile f(dir.file("to_null")); }).find("not a regular file"), std::string::npos);
  for (const auto& e : fs::directory_iterator(dir.path()))
    EXPECT_EQ(e.path().filename().string().find(".tmp."), std::string::npos) << e.path();
}

TEST(AtomicFile, PlantedSymlinksNeverGetWrittenThrough) {
  const test_support::ScratchDir dir("onetip-atomic");
  const fs::path victim = dir.path() / "victim.txt";
  std::ofstream(victim) << "precious";
  // the staging name of earlier versions, planted for this very process
  const fs::path target = dir.path() / "out.csv";
  fs::create_symlink(victim, target.string() + ".tmp." + std::to_string(::getpid()));
  writeAtomically(target.string(), "new");
  EXPECT_EQ(readAll(victim), "precious");
  EXPECT_EQ(readAll(target), "new");
  // the target itself a symlink: the link is replaced, its pointee untouched
  const fs::path link = dir.path() / "link.csv";
  fs::create_symlink(victim, link);
  writeAtomically(link.string(), "replaced");
  EXPECT_FALSE(fs::is_symlink(link));
  EXPECT_EQ(readAll(link), "replaced");
  EXPECT_EQ(readAll(victim), "precious");
}

TEST(AtomicFile, WithoutCommitNothingIsLeftAndTheTargetIsUntouched) {
  const test_support::ScratchDir dir("onetip-atomic");
  const fs::path target = dir.path() / "keep.csv";
  std::ofstream(target) << "old";
  {
    AtomicFile f(target.string());
    f.stream() << "half";
  }
  EXPECT_EQ(readAll(target), "old");
  size_t entries = 0;
  for (const auto& e : fs::directory_iterator(dir.path())) entries += e.path() == target ? 1 : 100;
  EXPECT_EQ(entries, 1u);
}

TEST(AtomicFile, CommittedFileHasTheUmasksRegularMode) {
  const test_support::ScratchDir dir("onetip-atomic");
  const mode_t old = ::umask(022);
  writeAtomically(dir.file("m.csv"), "x");
  ::umask(old);
  struct stat st {};
  ASSERT_EQ(::stat(dir.file("m.csv").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0644u);
}

// Issue 39: a write error is known at the record that met it, with its cause;
// what was flushed whole can be kept, and a record refused for want of space is
// written again once there is room. Run in a child under a file-size limit.
TEST(AtomicFile, AFailedFlushNamesItsCauseKeepsWholeRecordsAndRetries) {
  const test_support::ScratchDir dir("onetip-atomic");
  const std::string kept = dir.file("kept.csv"), retried = dir.file("retried.csv");
  const pid_t child = ::fork();
  if (child == 0) {
    ::signal(SIGXFSZ, SIG_IGN);
    rlimit limit{};
    ::getrlimit(RLIMIT_FSIZE, &limit);
    limit.rlim_cur = 100;
    ::setrlimit(RLIMIT_FSIZE, &limit);
    int code = 0;
    {
      AtomicFile f(kept);  // records of 30 bytes: the fourth does not fit
      std::string message;
      for (int i = 0; i < 10 && message.empty(); ++i) {
        f.stream() << std::string(29, static_cast<char>('a' + i)) << '\n';
        try {
          f.flush();
        } catch (const InputError& e) {
          message = e.what();
        }
      }
      if (message.find("File too large") == std::string::npos) code |= 1;
      f.commitFlushed();
    }
    {
      AtomicFile f(retried);
      f.stream() << std::string(80, 'x') << '\n';
      f.flush();
      f.stream() << std::string(29, 'y') << '\n';  // still wholly in the buffer when refused
      try {
        f.flush();
        code |= 2;
      } catch (const InputError&) {
      }
      limit.rlim_cur = limit.rlim_max;  // room again
      ::setrlimit(RLIMIT_FSIZE, &limit);
      f.flush();
      f.commit();
    }
    ::_exit(code);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(readAll(kept), std::string(29, 'a') + "\n" + std::string(29, 'b') + "\n" + std::string(29, 'c') + "\n");
  EXPECT_EQ(readAll(retried), std::string(80, 'x') + "\n" + std::string(29, 'y') + "\n");
  for (const auto& e : fs::directory_iterator(dir.path()))
    EXPECT_EQ(e.path().filename().string().find(".tmp."), std::string::npos) << e.path();
}

}  // namespace
