// AtomicFile against hostile targets (core/atomic_file.hpp): a device, a
// folder or a FIFO is refused; a planted symlink at the old staging name, or
// as the target, never gets its pointee written. (Which staging of killed runs
// is removed: test_staging_owner.cpp.)
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/atomic_file.hpp"
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

}  // namespace
