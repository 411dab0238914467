// The spnav socket file: owner-only permissions whatever the umask, stale
// sockets replaced, live sockets and non-sockets refused, clear errors.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <fcntl.h>
#include <sys/file.h>
#include <thread>
#include <vector>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include "core/error.hpp"
#include "os_outputs/unix_listener.hpp"
#include "test_support.hpp"

namespace onetip::os_outputs {
namespace {

namespace fs = std::filesystem;

class UnixListenerTest : public ::testing::Test {
 protected:
  void SetUp() override { path_ = (dir_ / "spnav.sock").string(); }

  static bool canConnect(const std::string& path) {
    const int s = ::socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    std::snprintf(addr.sun_path, sizeof(addr.sun_path), "%s", path.c_str());
    const bool ok = ::connect(s, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) == 0;
    ::close(s);
    return ok;
  }

  static std::string errorOf(const std::string& path) {
    try {
      UnixListener::listenAt(path, 4);
    } catch (const InputError& e) {
      return e.what();
    }
    return {};
  }

  testing::ScratchDir scratch_;
  const fs::path& dir_ = scratch_.path();
  std::string path_;
};

TEST_F(UnixListenerTest, SocketIsOwnerOnlyEvenWithAnOpenUmask) {
  const mode_t old = ::umask(0);
  UnixListener l = UnixListener::listenAt(path_, 4);
  ::umask(old);
  struct stat st {};
  ASSERT_EQ(::lstat(path_.c_str(), &st), 0);
  EXPECT_TRUE(S_ISSOCK(st.st_mode));
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  EXPECT_TRUE(canConnect(path_));
  // Nothing but the socket and its lock file is in the directory (no temporary leftovers).
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 2);
  EXPECT_TRUE(fs::is_regular_file(path_ + ".lock"));
  l.close();
  EXPECT_FALSE(fs::exists(fs::symlink_status(path_)));
  EXPECT_FALSE(fs::exists(fs::symlink_status(path_ + ".lock")));
}

TEST_F(UnixListenerTest, StaleSocketIsReplaced) {
  {
    const int s = ::socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    std::snprintf(addr.sun_path, sizeof(addr.sun_path), "%s", path_.c_str());
    ASSERT_EQ(::bind(s, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)), 0);
    ::close(s);  // the file stays behind, nobody listens: stale
  }
  ASSERT_FALSE(canConnect(path_));
  UnixListener l = UnixListener::listenAt(path_, 4);
  EXPECT_TRUE(canConnect(path_));
}

TEST_F(UnixListenerTest, LiveSocketIsRefusedAndKeepsWorking) {
  UnixListener first = UnixListener::listenAt(path_, 4);
  const std::string err = errorOf(path_);
  EXPECT_NE(err.find(path_), std::string::npos) << err;
  EXPECT_NE(err.find("another server"), std::string::npos) << err;
  EXPECT_TRUE(canConnect(path_));
}

// Issue 39: two servers started together could both pass the probe for a live
// socket (nothing listens yet) and both run, one serving nobody. A server that
// is starting holds the lock beside the path: the other is refused.
TEST_F(UnixListenerTest, AServerStillStartingHoldsThePathAgainstASecond) {
  const int starting = ::open((path_ + ".lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0600);
  ASSERT_GE(starting, 0);
  ASSERT_EQ(::flock(starting, LOCK_EX | LOCK_NB), 0);
  const std::string err = errorOf(path_);
  EXPECT_NE(err.find("another server"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(fs::symlink_status(path_)));  // no socket was made
  ::close(starting);  // it went away without a socket: the path is free again
  UnixListener l = UnixListener::listenAt(path_, 4);
  EXPECT_TRUE(canConnect(path_));
}

TEST_F(UnixListenerTest, OfTwoServersStartedTogetherOneRuns) {
  for (int trial = 0; trial < 20; ++trial) {
    std::atomic<bool> go{false};
    std::atomic<int> listening{0};
    std::vector<UnixListener> kept(2);
    std::vector<std::thread> servers;
    for (int i = 0; i < 2; ++i)
      servers.emplace_back([&, i] {
        while (!go) std::this_thread::yield();
        try {
          kept[static_cast<size_t>(i)] = UnixListener::listenAt(path_, 4);
          ++listening;
        } catch (const InputError&) {
        }
      });
    go = true;
    for (auto& t : servers) t.join();
    EXPECT_EQ(listening.load(), 1) << "trial " << trial;
  }
}

TEST_F(UnixListenerTest, NonSocketIsNeverReplaced) {
  { std::ofstream(path_) << "precious"; }
  const std::string err = errorOf(path_);
  EXPECT_NE(err.find("not a socket"), std::string::npos) << err;
  std::ifstream in(path_);
  std::string content;
  in >> content;
  EXPECT_EQ(content, "precious");
  fs::remove(path_);
  fs::create_symlink("/tmp", path_);
  EXPECT_NE(errorOf(path_).find("not a socket"), std::string::npos);
}

TEST_F(UnixListenerTest, BadPathsNameThePath) {
  const std::string missing = (dir_ / "no-such-dir" / "s.sock").string();
  std::string err = errorOf(missing);
  EXPECT_NE(err.find(missing), std::string::npos) << err;
  EXPECT_NE(err.find("does not exist"), std::string::npos) << err;
  const std::string too_long = (dir_ / std::string(200, 'x')).string();
  err = errorOf(too_long);
  EXPECT_NE(err.find("bytes long"), std::string::npos) << err;
  EXPECT_NE(errorOf("").find("bytes long"), std::string::npos);
}

}  // namespace
}  // namespace onetip::os_outputs
