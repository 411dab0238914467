// tests/dds/publisher_process.hpp — a sensed-vector publisher in a forked copy
// of the test, as a second machine or an intruder would be: optionally in
// another network namespace (setns into /run/netns/NAME, as `ip netns exec`
// does) and with its own CYCLONEDDS_URI (a DDS Security identity, or none).
// Fork it before the test starts threads (the Maestro emulator) or DDS.
// It publishes for a set time, or until SIGTERM. Its exit status says whether
// any reader ever matched its writer (1) or none did (0); 2: it could not
// enter the namespace.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sched.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "child_process.hpp"
#include "dds/participant.hpp"
#include "dds/sensed_vector_link.hpp"
#include "scoped_env.hpp"

namespace onetip::test_support {

struct PublisherPlan {
  dds::DdsOptions net;                 // domain, namespace, interface and peers as seen from its namespace
  std::string netns;                   // network namespace to publish from; empty: the test's own
  std::optional<std::string> uri;      // its CYCLONEDDS_URI; nullopt: none (no DDS Security)
  std::string sensor = "biotac_like";  // the name it announces in each sample
  std::vector<double> values;
  double rate_hz = 100;
  double seconds = 1;                  // how long it publishes; 0: until SIGTERM
  bool wait_for_reader = true;         // first wait (up to 10 s) for a reader to match
  double start_after_s = 0;            // then wait this long before the first sample
};

inline volatile std::sig_atomic_t g_publisher_stop = 0;
inline void stopPublisher(int) { g_publisher_stop = 1; }

// What the forked child runs: ChildProcess publisher(publisherBody(plan)).
inline std::function<int()> publisherBody(const PublisherPlan& plan) {
  return [plan] {
    struct sigaction sa {};
    sa.sa_handler = stopPublisher;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGTERM, &sa, nullptr);
    using Clock = std::chrono::steady_clock;
    if (!plan.netns.empty()) {
      const int fd = ::open(("/run/netns/" + plan.netns).c_str(), O_RDONLY | O_CLOEXEC);
      if (fd < 0 || ::setns(fd, CLONE_NEWNET) != 0) return 2;
      ::close(fd);
    }
    const ScopedEnv env("CYCLONEDDS_URI", plan.uri);
    dds::Participant participant(plan.net);
    dds::SensedVectorPublisher writer(participant, plan.sensor);
    bool matched = false;
    const auto made = Clock::now(), give_up = made + std::chrono::seconds(10);
    while (plan.wait_for_reader && writer.matchedReaders() == 0 && Clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (plan.wait_for_reader)  // with DDS Security this includes the handshake
      std::printf("publisher '%s': a reader matched %.0f ms after its writer was made\n", plan.sensor.c_str(),
                  std::chrono::duration<double, std::milli>(Clock::now() - made).count());
    std::fflush(stdout);  // the child ends with _exit
    std::this_thread::sleep_for(std::chrono::duration<double>(plan.start_after_s));
    const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1 / plan.rate_hz));
    const auto end = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(plan.seconds));
    for (auto next = Clock::now(); !g_publisher_stop && (plan.seconds <= 0 || Clock::now() < end);) {
      writer.publish(std::chrono::duration<double>(Clock::now().time_since_epoch()).count(), plan.values);
      matched = matched || writer.matchedReaders() > 0;
      next += period;
      std::this_thread::sleep_until(next);
    }
    return matched ? 1 : 0;
  };
}

}  // namespace onetip::test_support
