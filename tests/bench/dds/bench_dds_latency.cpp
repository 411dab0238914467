// bench_dds_latency — one-way latency of onetip's DDS streams, publisher
// (onetip_dds on Cyclone DDS, this process) to subscriber, per stream:
//   Loopback/*:    the Fast DDS subscriber tests/dds/ros_topic_recorder in a
//                  child process, both on 127.0.0.1 (unicast discovery);
//   Namespaces/*:  this process moved into network namespace A, the recorder
//                  in B, joined by a veth pair (skipped where namespaces cannot
//                  be made);
//   InProcess/*:   a Cyclone reader in this process (the in-process figure).
// Frames30Hz publishes what `onetip publish` sends per camera frame at 30 fps
// (joy, pose, markers: 289 markers = 11.6 kB, one event, a 75-channel sensed
// vector); Sensed1kHz a 20-channel sensed vector every 1 ms (the display loop's
// rate). Latency = the subscriber's reception time minus the writer's source
// timestamp (one wall clock: one machine). Counters: <topic>_p50_us,
// <topic>_p99_us and <topic>_lost (samples sent but not received).
#include <benchmark/benchmark.h>
#include <fcntl.h>
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include "child_process.hpp"
#include "dds/input_publisher.hpp"
#include "dds/sensed_vector_link.hpp"
#include "pipeline/frame_processor.hpp"
#include "scratch_dir.hpp"
#include "veth_namespaces.hpp"

namespace {

using namespace onetip;
using Clock = std::chrono::steady_clock;
using test_support::ChildProcess;

pipeline::FrameResult syntheticFrame(double t) {
  pipeline::FrameResult r;
  r.status = pipeline::FrameStatus::ok;
  r.t = t;
  r.markers = MarkerField(17, 17);
  for (int i = 0; i < r.markers.size(); ++i) {
    r.markers.position[static_cast<size_t>(i)] = {1.2 * (i % 17) - 9.6, 1.2 * (i / 17) - 9.6, 0.01 * t};
    r.markers.valid[static_cast<size_t>(i)] = 1;
  }
  r.pose.contact = true;
  r.pose.input = r.pose.raw = Input6{0.1, 0.2, 1.0, 2.0, 3.0, 4.0};
  return r;
}

struct Stats {
  double p50 = 0, p99 = 0;
  size_t n = 0;
};
Stats stats(std::vector<double> v) {
  Stats s;
  s.n = v.size();
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  s.p50 = v[v.size() / 2];
  s.p99 = v[std::min(v.size() - 1, static_cast<size_t>(0.99 * static_cast<double>(v.size())))];
  return s;
}

// Runs `publish(i)` every period for the benchmark's iterations, after the recorder matched.
template <typename Publish>
void paced(benchmark::State& state, double period_s, Publish&& publish) {
  auto next = Clock::now();
  long i = 0;
  for (auto _ : state) {
    publish(i++);
    next += std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(period_s));
    std::this_thread::sleep_until(next);
  }
}

enum class Load { frames_30hz, sensed_1khz };

// Publishes `load` with this process's participant `net` to the recorder run by `prefix` on `rec_net`.
void toRecorder(benchmark::State& state, Load load, const dds::DdsOptions& net, const std::string& prefix,
                const std::string& rec_net) {
  test_support::ScratchDir dir("onetip-bench-dds");
  ChildProcess recorder(prefix + ROS_TOPIC_RECORDER + " --domain " + std::to_string(net.domain) + " --namespace " +
                            net.ros_namespace + " " + rec_net + " --out " + dir.path().string() +
                            " --duration 120 --idle 1",
                        dir.file("recorder.log"));
  std::map<std::string, long> sent;
  {
    dds::Participant participant(net);
    dds::InputPublisher frames(participant);
    dds::SensedVectorPublisher sensed(participant, "bench");
    const auto give_up = Clock::now() + std::chrono::seconds(20);
    while ((frames.matchedReaders() == 0 || sensed.matchedReaders() == 0) && Clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    if (frames.matchedReaders() == 0 || sensed.matchedReaders() == 0) {
      state.SkipWithError("the recorder did not match within 20 s");
      return;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(500));  // let discovery settle on both sides
    if (load == Load::frames_30hz) {
      const std::vector<double> v(75, 0.01);
      input::InputEvent e{EventType::state_changed, 0, {}, ContactState::stick, {}};
      paced(state, 1.0 / 30, [&](long i) {
        frames.publishFrame(syntheticFrame(static_cast<double>(i) / 30), std::chrono::steady_clock::now());
        frames.publishEvent(i, e, std::chrono::steady_clock::now());
        sensed.publish(static_cast<double>(i) / 30, v);
      });
      for (const char* t : {"joy", "pose", "markers", "events", "haptic/sensed"}) sent[t] = state.iterations();
    } else {
      const std::vector<double> v(20, 2000.0);
      paced(state, 1e-3, [&](long i) { sensed.publish(static_cast<double>(i) * 1e-3, v); });
      sent["haptic/sensed"] = state.iterations();
    }
  }
  if (recorder.wait(60) != 0) {
    state.SkipWithError(("recorder failed: " + recorder.log()).c_str());
    return;
  }
  std::map<std::string, std::vector<double>> lat;
  std::ifstream in(dir.file("latency.csv"));
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string topic, stamp, us;
    std::getline(ss, topic, ',');
    std::getline(ss, stamp, ',');
    std::getline(ss, us, ',');
    lat[topic].push_back(std::stod(us));
  }
  for (const auto& [topic, n] : sent) {
    const Stats s = stats(lat[topic]);
    const std::string k = topic == "haptic/sensed" ? "sensed" : topic;
    state.counters[k + "_p50_us"] = s.p50;
    state.counters[k + "_p99_us"] = s.p99;
    state.counters[k + "_lost"] = static_cast<double>(n - static_cast<long>(s.n));
  }
}

dds::DdsOptions netOn(const std::string& interface, const std::string& peer) {
  dds::DdsOptions o;
  static int run = 0;
  o.domain = 1 + (::getpid() + run++) % 200;
  o.ros_namespace = "onetip_bench_" + std::to_string(::getpid()) + "_" + std::to_string(run);
  o.interface = interface;
  o.peers = {peer};
  return o;
}

void BM_Loopback(benchmark::State& state, Load load) {
  toRecorder(state, load, netOn("lo", "127.0.0.1"), "", "--address 127.0.0.1 --peer 127.0.0.1");
}

void BM_Namespaces(benchmark::State& state, Load load) {
  test_support::VethNamespaces net;
  const std::string why = net.create();
  if (!why.empty()) {
    state.SkipWithError(("network namespaces unavailable: " + why).c_str());
    for (auto _ : state) {
    }
    return;
  }
  // This thread (and the DDS threads it starts) into A for the run, then back.
  const int home = ::open("/proc/self/ns/net", O_RDONLY);
  const int ns_a = ::open(("/var/run/netns/" + net.namespaceA()).c_str(), O_RDONLY);
  if (home < 0 || ns_a < 0 || ::setns(ns_a, CLONE_NEWNET) != 0) {
    state.SkipWithError("cannot enter network namespace A");
    for (auto _ : state) {
    }
  } else {
    toRecorder(state, load, netOn(net.vethA(), net.addressB()), net.execInB(),
               "--address " + net.addressB() + " --peer " + net.addressA());
    ::setns(home, CLONE_NEWNET);
  }
  if (home >= 0) ::close(home);
  if (ns_a >= 0) ::close(ns_a);
}

// Cyclone to Cyclone in one process: the sensed stream's in-process figure
// (latency of the newest sample per wake-up of the reading thread).
void BM_InProcess(benchmark::State& state, Load load) {
  const dds::DdsOptions net = netOn("lo", "127.0.0.1");
  dds::Participant participant(net);
  dds::SensedVectorPublisher pub(participant, "bench");
  dds::SensedVectorSubscriber sub(participant);
  std::vector<double> lat_us;
  std::atomic<bool> done{false};
  std::thread reader([&] {
    dds::SensedSample s;
    while (!done) {
      if (sub.waitForData(0.05) && sub.takeNewest(s)) lat_us.push_back(s.latency_ms * 1e3);
    }
  });
  const std::vector<double> v(load == Load::frames_30hz ? 75 : 20, 1.0);
  paced(state, load == Load::frames_30hz ? 1.0 / 30 : 1e-3,
        [&](long i) { pub.publish(static_cast<double>(i), v); });
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  done = true;
  reader.join();
  const Stats s = stats(lat_us);
  state.counters["sensed_p50_us"] = s.p50;
  state.counters["sensed_p99_us"] = s.p99;
  state.counters["sensed_lost"] = static_cast<double>(state.iterations() - static_cast<long>(sub.received()));
}


}  // namespace

BENCHMARK_CAPTURE(BM_InProcess, Sensed1kHz, Load::sensed_1khz)->Iterations(3000)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Loopback, Frames30Hz, Load::frames_30hz)->Iterations(300)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Loopback, Sensed1kHz, Load::sensed_1khz)->Iterations(3000)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Namespaces, Frames30Hz, Load::frames_30hz)->Iterations(300)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Namespaces, Sensed1kHz, Load::sensed_1khz)->Iterations(3000)->UseRealTime()->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
