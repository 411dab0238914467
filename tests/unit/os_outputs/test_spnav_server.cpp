// The spnav server against the real libspnav client from Debian (SPNAV_SOCKET)
// and against raw sockets playing slow, early or malicious clients. Expected
// values are worked out by hand from axis_scaling.hpp (±4 mm, 3 mm, ±40 deg,
// ±15 deg -> ±350 units).
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <poll.h>
#include <spnav.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <thread>
#include <unistd.h>
#include <vector>

#include "core/error.hpp"
#include "os_outputs/spnav_server.hpp"
#include "test_support.hpp"

namespace onetip::os_outputs {
namespace {

namespace fs = std::filesystem;
using input::EventType;
using input::InputEvent;
using Clock = std::chrono::steady_clock;

using testing::makeEvent;

Input6 sampleA() {  // -> {175, -105, 70, -70, 140, -140}
  Input6 in;
  in.dx = 2, in.dy = -1.2, in.dz = 0.6, in.yaw = -6, in.pitch = -8, in.roll = 16;
  return in;
}

// The libspnav connection (one per process: the library keeps global state).
class LibspnavClient {
 public:
  explicit LibspnavClient(const std::string& path) {
    ::setenv("SPNAV_SOCKET", path.c_str(), 1);
    ok_ = spnav_open() == 0;
  }
  ~LibspnavClient() {
    if (ok_) spnav_close();
  }
  bool ok() const { return ok_; }
  // The next event within timeout_ms, or false.
  static bool next(spnav_event& ev, int timeout_ms) {
    pollfd p{spnav_fd(), POLLIN, 0};
    if (::poll(&p, 1, timeout_ms) <= 0) return false;
    return spnav_poll_event(&ev) > 0;
  }

 private:
  bool ok_ = false;
};

std::array<int, 6> motionOf(const spnav_event& ev) {
  return {ev.motion.x, ev.motion.y, ev.motion.z, ev.motion.rx, ev.motion.ry, ev.motion.rz};
}

// A hand-driven client socket.
class RawClient {
 public:
  explicit RawClient(const std::string& path) {
    fd_ = ::socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    std::snprintf(addr.sun_path, sizeof(addr.sun_path), "%s", path.c_str());
    connected_ = ::connect(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) == 0;
  }
  ~RawClient() { ::close(fd_); }
  bool connected() const { return connected_; }
  void send(const void* p, size_t n) { ASSERT_EQ(::send(fd_, p, n, MSG_NOSIGNAL), static_cast<ssize_t>(n)); }
  void sendWord(std::int32_t w) { send(&w, sizeof(w)); }
  // Reads exactly n bytes within timeout_ms.
  bool recvExact(void* p, size_t n, int timeout_ms) {
    auto* out = static_cast<char*>(p);
    const auto deadline = Clock::now() + std::chrono::milliseconds(timeout_ms);
    while (n > 0) {
      const int left = static_cast<int>(
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count());
      pollfd pfd{fd_, POLLIN, 0};
      if (left <= 0 || ::poll(&pfd, 1, left) <= 0) return false;
      const ssize_t got = ::recv(fd_, out, n, 0);
      if (got <= 0) return false;
      out += got;
      n -= static_cast<size_t>(got);
    }
    return true;
  }
  // True when the server closes the connection within timeout_ms.
  bool closedByServer(int timeout_ms) {
    const auto deadline = Clock::now() + std::chrono::milliseconds(timeout_ms);
    char sink[256];
    while (Clock::now() < deadline) {
      pollfd pfd{fd_, POLLIN, 0};
      if (::poll(&pfd, 1, 50) > 0) {
        const ssize_t got = ::recv(fd_, sink, sizeof(sink), 0);
        if (got == 0 || (got < 0 && errno == ECONNRESET)) return true;
      }
    }
    return false;
  }

 private:
  int fd_ = -1;
  bool connected_ = false;
};

class SpnavServerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    options_.socket_path = (dir_ / "spnav.sock").string();
    options_.hello_timeout_ms = 100;
  }

  template <typename Pred>
  static bool waitFor(Pred pred, int timeout_ms = 3000) {
    const auto deadline = Clock::now() + std::chrono::milliseconds(timeout_ms);
    while (!pred()) {
      if (Clock::now() > deadline) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return true;
  }

  testing::ScratchDir scratch_;
  const fs::path& dir_ = scratch_.path();
  SpnavServerOptions options_;
};

TEST_F(SpnavServerTest, LibspnavReceivesScaledMotionButtonsAndTheZero) {
  SpnavServer server(options_);
  server.start();
  struct stat st {};
  ASSERT_EQ(::lstat(options_.socket_path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);

  LibspnavClient client(options_.socket_path);
  ASSERT_TRUE(client.ok());
  EXPECT_EQ(spnav_protocol(), 1);  // the v1 handshake went through
  char name[64] = {};
  EXPECT_GT(spnav_dev_name(name, sizeof(name)), 0);
  EXPECT_STREQ(name, "onetip tactile fingertip");
  EXPECT_EQ(spnav_dev_axes(), 6);
  EXPECT_EQ(spnav_dev_buttons(), 1);
  EXPECT_EQ(spnav_client_name("onetip unit test"), 0);

  Input6 beyond;
  beyond.dx = 10;     // saturates at +350
  beyond.roll = -60;  // saturates at -350
  server.publish(makeEvent(EventType::contact_begin, 1.00));
  server.publish(makeEvent(EventType::input, 1.00, sampleA()));
  server.publish(makeEvent(EventType::input, 1.01, beyond));
  server.publish(makeEvent(EventType::press, 1.02));
  server.publish(makeEvent(EventType::release, 1.03));
  server.publish(makeEvent(EventType::contact_end, 1.05));

  spnav_event ev{};
  ASSERT_TRUE(LibspnavClient::next(ev, 2000));
  ASSERT_EQ(ev.type, SPNAV_EVENT_MOTION);
  EXPECT_EQ(motionOf(ev), (std::array<int, 6>{175, -105, 70, -70, 140, -140}));
  EXPECT_EQ(ev.motion.period, 0u);
  ASSERT_TRUE(LibspnavClient::next(ev, 2000));
  ASSERT_EQ(ev.type, SPNAV_EVENT_MOTION);
  EXPECT_EQ(motionOf(ev), (std::array<int, 6>{350, 0, 0, 0, -350, 0}));
  EXPECT_EQ(ev.motion.period, 10u);
  ASSERT_TRUE(LibspnavClient::next(ev, 2000));
  ASSERT_EQ(ev.type, SPNAV_EVENT_BUTTON);
  EXPECT_EQ(ev.button.press, 1);
  EXPECT_EQ(ev.button.bnum, 0);
  ASSERT_TRUE(LibspnavClient::next(ev, 2000));
  ASSERT_EQ(ev.type, SPNAV_EVENT_BUTTON);
  EXPECT_EQ(ev.button.press, 0);
  ASSERT_TRUE(LibspnavClient::next(ev, 2000));
  ASSERT_EQ(ev.type, SPNAV_EVENT_MOTION);
  EXPECT_EQ(motionOf(ev), (std::array<int, 6>{}));  // the explicit zero at contact end
  EXPECT_EQ(ev.motion.period, 40u);
  EXPECT_FALSE(LibspnavClient::next(ev, 50));  // nothing else

  server.stop();
  EXPECT_FALSE(fs::exists(fs::symlink_status(options_.socket_path)));
}

TEST_F(SpnavServerTest, EventMaskAndV0SensitivityPerClient) {
  SpnavServer server(options_);
  server.start();
  LibspnavClient client(options_.socket_path);
  ASSERT_TRUE(client.ok());
  ASSERT_EQ(spnav_evmask(SPNAV_EVMASK_MOTION), 0);  // no buttons for this client
  // libspnav 1.0 sends the low half of the double 2.0, i.e. 0: acknowledged,
  // ignored (the client keeps sensitivity 1 instead of being muted).
  EXPECT_EQ(spnav_sensitivity(2.0), 0);
  RawClient v0(options_.socket_path);               // an old client: v0, sensitivity 2
  ASSERT_TRUE(v0.connected());
  v0.sendWord(std::bit_cast<std::int32_t>(2.0f));
  ASSERT_TRUE(waitFor([&] { return server.stats().clients == 2; }));
  std::this_thread::sleep_for(std::chrono::milliseconds(150));  // the v0 word is read

  server.publish(makeEvent(EventType::press, 0));
  server.publish(makeEvent(EventType::input, 0, sampleA()));
  spnav_event ev{};
  ASSERT_TRUE(LibspnavClient::next(ev, 2000));
  EXPECT_EQ(ev.type, SPNAV_EVENT_MOTION);  // the press was masked out
  EXPECT_EQ(motionOf(ev), (std::array<int, 6>{175, -105, 70, -70, 140, -140}));
  std::int32_t raw[16];
  ASSERT_TRUE(v0.recvExact(raw, sizeof(raw), 2000));
  EXPECT_EQ(raw[0], 1);  // press
  EXPECT_EQ(raw[8], 0);  // motion, doubled by the client's sensitivity
  EXPECT_EQ(std::vector<int>(raw + 9, raw + 15), (std::vector<int>{350, -210, 140, -140, 280, -280}));
}

TEST_F(SpnavServerTest, HandshakeReplyIsNeverPrecededByAnEvent) {
  SpnavServer server(options_);
  server.start();
  RawClient c(options_.socket_path);
  ASSERT_TRUE(c.connected());
  ASSERT_TRUE(waitFor([&] { return server.stats().clients == 1; }));
  server.publish(makeEvent(EventType::input, 0, sampleA()));  // before the client says hello
  c.sendWord(0x7faa5501);
  std::int32_t reply = 0;
  ASSERT_TRUE(c.recvExact(&reply, sizeof(reply), 2000));
  EXPECT_EQ(reply, 0x7faa5501);
  std::int32_t motion[8];
  ASSERT_TRUE(c.recvExact(motion, sizeof(motion), 2000));
  EXPECT_EQ(motion[0], 0);
  EXPECT_EQ(motion[1], 175);
}

TEST_F(SpnavServerTest, SilentClientGetsEventsAfterTheHelloTimeout) {
  SpnavServer server(options_);
  server.start();
  RawClient c(options_.socket_path);  // libspnav < 1.0 never writes anything
  ASSERT_TRUE(waitFor([&] { return server.stats().clients == 1; }));
  server.publish(makeEvent(EventType::input, 0, sampleA()));
  std::int32_t motion[8];
  ASSERT_TRUE(c.recvExact(motion, sizeof(motion), 2000));
  EXPECT_EQ(std::vector<int>(motion, motion + 7), (std::vector<int>{0, 175, -105, 70, -70, 140, -140}));
}

TEST_F(SpnavServerTest, ClientThatNeverReadsStallsNeitherServerNorOthers) {
  options_.idle_timeout_ms = 3600000;  // here the stuck client stays (its eviction: StalledReaderIsEvicted...)
  SpnavServer server(options_);
  server.start();
  RawClient stuck(options_.socket_path);  // connects, then never reads
  ASSERT_TRUE(stuck.connected());
  LibspnavClient good(options_.socket_path);
  ASSERT_TRUE(good.ok());
  ASSERT_TRUE(waitFor([&] { return server.stats().clients == 2; }));
  std::this_thread::sleep_for(std::chrono::milliseconds(150));  // the stuck client is past its hello

  constexpr int kEvents = 20000;
  std::atomic<int> received{0};
  std::atomic<bool> values_ok{true}, saw_zero{false};
  std::thread reader([&] {
    spnav_event ev{};
    while (LibspnavClient::next(ev, 5000)) {
      if (ev.type != SPNAV_EVENT_MOTION) continue;
      const int k = received.load();
      if (k == kEvents) {
        saw_zero = motionOf(ev) == std::array<int, 6>{};
        received = k + 1;
        return;
      }
      const int expected_x = static_cast<int>(std::lround(((k % 7) + 1) * 0.5 / 4 * 350));
      if (ev.motion.x != expected_x) values_ok = false;
      received = k + 1;
    }
  });
  double worst_publish_ms = 0;
  for (int i = 0; i < kEvents; ++i) {
    Input6 in;
    in.dx = ((i % 7) + 1) * 0.5;  // 0.5 .. 3.5 mm, never zero
    const auto t0 = Clock::now();
    server.publish(makeEvent(EventType::input, i * 0.001, in));
    worst_publish_ms = std::max(worst_publish_ms,
                                std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    // Pace on the good client only, so it never overflows its own queue.
    if (i % 200 == 199 && !waitFor([&] { return received.load() >= i + 1; }, 5000)) {
      ADD_FAILURE() << "the good client stopped receiving at event " << i;
      break;
    }
  }
  server.publish(makeEvent(EventType::contact_end, kEvents * 0.001));
  reader.join();  // returns after the zero, or 5 s after the last event
  EXPECT_EQ(received.load(), kEvents + 1);
  EXPECT_TRUE(values_ok.load());
  EXPECT_TRUE(saw_zero.load());
  const SpnavServerStats s = server.stats();
  EXPECT_EQ(s.clients, 2);                 // the stuck client is merely behind
  EXPECT_GT(s.messages_dropped, 0u);       // ... and loses its own oldest events
  EXPECT_LT(worst_publish_ms, 1000.0);     // liveness bound only: publish never waited on it
  RecordProperty("worst_publish_ms", std::to_string(worst_publish_ms));
  RecordProperty("dropped_for_stuck_client", std::to_string(s.messages_dropped));
  std::printf("worst publish() %.3f ms over %d events; %llu events dropped for the stuck client\n",
              worst_publish_ms, kEvents, static_cast<unsigned long long>(s.messages_dropped));
}

TEST_F(SpnavServerTest, GarbageSendersAreDisconnectedOthersUnaffected) {
  SpnavServer server(options_);
  server.start();
  LibspnavClient good(options_.socket_path);
  ASSERT_TRUE(good.ok());

  RawClient v1(options_.socket_path);
  v1.sendWord(0x7faa5501);
  std::int32_t reply = 0;
  ASSERT_TRUE(v1.recvExact(&reply, sizeof(reply), 2000));
  const std::uint32_t junk[8] = {0xdeadbeef, 1, 2, 3, 4, 5, 6, 7};
  v1.send(junk, sizeof(junk));
  EXPECT_TRUE(v1.closedByServer(2000));

  RawClient v0(options_.socket_path);
  v0.sendWord(std::bit_cast<std::int32_t>(std::nanf("")));
  EXPECT_TRUE(v0.closedByServer(2000));
  EXPECT_EQ(server.stats().garbage_disconnects, 2u);

  server.publish(makeEvent(EventType::input, 0, sampleA()));
  spnav_event ev{};
  ASSERT_TRUE(LibspnavClient::next(ev, 2000));
  EXPECT_EQ(motionOf(ev), (std::array<int, 6>{175, -105, 70, -70, 140, -140}));
}

TEST_F(SpnavServerTest, ConnectionsBeyondMaxClientsAreClosed) {
  options_.max_clients = 2;
  SpnavServer server(options_);
  server.start();
  RawClient a(options_.socket_path), b(options_.socket_path);
  ASSERT_TRUE(waitFor([&] { return server.stats().clients == 2; }));
  RawClient c(options_.socket_path);
  EXPECT_TRUE(c.closedByServer(2000));
  EXPECT_EQ(server.stats().refused, 1u);
  EXPECT_EQ(server.stats().clients, 2);
}

TEST_F(SpnavServerTest, IdleClientsNeverLockOutANewOne) {
  options_.max_clients = 2;
  options_.idle_timeout_ms = 300;
  SpnavServer server(options_);
  server.start();
  RawClient a(options_.socket_path);
  ASSERT_TRUE(waitFor([&] { return server.stats().clients == 1; }));
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // a is the older idle client
  RawClient b(options_.socket_path);
  ASSERT_TRUE(waitFor([&] { return server.stats().clients == 2; }));
  RawClient early(options_.socket_path);  // both were active within the time-out: refused
  EXPECT_TRUE(early.closedByServer(2000));
  EXPECT_EQ(server.stats().refused, 1u);
  std::this_thread::sleep_for(std::chrono::milliseconds(400));  // now both are idle
  RawClient late(options_.socket_path);
  EXPECT_TRUE(a.closedByServer(2000));  // the longest idle one made room
  EXPECT_TRUE(waitFor([&] { return server.stats().idle_evictions == 1 && server.stats().clients == 2; }));
  std::this_thread::sleep_for(std::chrono::milliseconds(150));  // past the newcomer's hello time-out
  server.publish(makeEvent(EventType::input, 0, sampleA()));
  std::int32_t message[8] = {};
  ASSERT_TRUE(late.recvExact(message, sizeof(message), 2000));
  EXPECT_EQ(message[0], 0);    // SPNAV_EVENT_MOTION (v0 wire type)
  EXPECT_EQ(message[1], 175);  // x
  EXPECT_EQ(server.stats().refused, 1u);
}

TEST_F(SpnavServerTest, StalledReaderIsEvictedAfterTheIdleTimeout) {
  options_.idle_timeout_ms = 300;
  SpnavServer server(options_);
  server.start();
  RawClient stuck(options_.socket_path);  // never reads: its socket buffer fills up
  ASSERT_TRUE(waitFor([&] { return server.stats().clients == 1; }));
  const auto start = Clock::now();
  Input6 in = sampleA();
  for (int i = 0; server.stats().idle_evictions == 0 && Clock::now() - start < std::chrono::seconds(20); ++i) {
    in.dx = (i % 2) ? 1.0 : 2.0;
    server.publish(makeEvent(EventType::input, i * 0.001, in));
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  EXPECT_EQ(server.stats().idle_evictions, 1u);
  EXPECT_TRUE(waitFor([&] { return server.stats().clients == 0; }));
  EXPECT_TRUE(stuck.closedByServer(5000));
}

TEST_F(SpnavServerTest, BadOptionsAndPathsGiveClearErrors) {
  SpnavServerOptions o = options_;
  o.socket_path = (dir_ / "missing" / "s.sock").string();
  SpnavServer bad_path(o);
  try {
    bad_path.start();
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(o.socket_path), std::string::npos) << e.what();
  }
  EXPECT_FALSE(bad_path.running());
  o = options_;
  o.max_queued_events = 0;
  try {
    SpnavServer(o).start();
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("max_queued_events"), std::string::npos) << e.what();
  }
  // Publishing to a server that is not running is harmless.
  SpnavServer idle(options_);
  idle.publish(makeEvent(EventType::input, 0, sampleA()));
  EXPECT_EQ(idle.stats().events_published, 0u);
}

}  // namespace
}  // namespace onetip::os_outputs
