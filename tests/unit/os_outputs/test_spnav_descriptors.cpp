// The spnav server within the open-file limit (issue 39 item 7): --max-clients
// 1024 under `ulimit -n 1024` ran out of descriptors, the accept loop spun on
// EMFILE and new clients hung. Now clients beyond the limit are refused at
// start (or the soft limit raised up to the hard one), and a client arriving
// while the process is out of descriptors is closed at once, not left hanging.
#include <gtest/gtest.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "core/error.hpp"
#include "os_outputs/spnav_server.hpp"
#include "sanitizer_leg.hpp"
#include "test_support.hpp"

namespace onetip::os_outputs {
namespace {

// Runs `body` in a child under the open-file limits soft/hard; its exit status (0: the checks held).
int inChildWithLimit(rlim_t soft, rlim_t hard, int (*body)(const std::string&), const std::string& socket_path) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const rlimit limit{soft, hard};
    ::_exit(::setrlimit(RLIMIT_NOFILE, &limit) == 0 ? body(socket_path) : 100);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

int startWith1024Clients(const std::string& socket_path) {
  SpnavServerOptions o;
  o.socket_path = socket_path;
  o.max_clients = 1024;
  SpnavServer server(o);
  try {
    server.start();
  } catch (const InputError& e) {
    const std::string m = e.what();
    return m.find("max_clients") != std::string::npos && m.find("open-file limit") != std::string::npos ? 10 : 11;
  }
  rlimit now{};
  ::getrlimit(RLIMIT_NOFILE, &now);
  return now.rlim_cur >= 1024 + 64 ? 20 : 21;  // started: the soft limit was raised to fit
}

TEST(SpnavDescriptors, MaxClientsBeyondTheOpenFileLimitIsRefusedNamingIt) {
  testing::ScratchDir dir;
  const std::string path = (dir.path() / "spnav.sock").string();
  EXPECT_EQ(inChildWithLimit(256, 256, startWith1024Clients, path), 10);    // cannot fit: refused
  EXPECT_EQ(inChildWithLimit(256, 4096, startWith1024Clients, path), 20);   // fits once raised
}

TEST(SpnavDescriptors, AClientArrivingWhenDescriptorsRunOutIsClosedAtOnce) {
  ONETIP_TAKES_EVERY_DESCRIPTOR_RELEASE_ONLY();
  testing::ScratchDir dir;
  SpnavServerOptions o;
  o.socket_path = (dir.path() / "spnav.sock").string();
  o.max_clients = 4;
  SpnavServer server(o);
  server.start();
  const int client = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  ASSERT_GE(client, 0);
  rlimit saved{};
  ASSERT_EQ(::getrlimit(RLIMIT_NOFILE, &saved), 0);
  rlimit low = saved;
  low.rlim_cur = std::min<rlim_t>(saved.rlim_cur, 512);  // a bounded number to take
  ASSERT_EQ(::setrlimit(RLIMIT_NOFILE, &low), 0);
  std::vector<int> hog;  // every descriptor left, so the server's accept meets EMFILE
  for (int fd; (fd = ::dup(client)) >= 0;) hog.push_back(fd);
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  std::snprintf(addr.sun_path, sizeof(addr.sun_path), "%s", o.socket_path.c_str());
  const bool connected = ::connect(client, reinterpret_cast<const sockaddr*>(&addr), sizeof(addr)) == 0;
  pollfd p{client, POLLIN, 0};
  const bool answered = connected && ::poll(&p, 1, 10000) == 1;  // the end of the stream, at once
  char byte = 0;
  const ssize_t got = answered ? ::recv(client, &byte, 1, MSG_DONTWAIT) : -1;
  for (const int fd : hog) ::close(fd);
  ::setrlimit(RLIMIT_NOFILE, &saved);
  ASSERT_TRUE(connected);
  EXPECT_TRUE(answered) << "the client hung";
  EXPECT_EQ(got, 0) << "closed, not served";
  EXPECT_EQ(server.stats().shed, 1u);
  EXPECT_EQ(server.stats().accepted, 0u);
  ::close(client);
  server.stop();
}

}  // namespace
}  // namespace onetip::os_outputs
