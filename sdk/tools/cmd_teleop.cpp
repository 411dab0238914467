// `onetip teleop`: the operator side of teleoperation. Subscribes to a remote
// sensed vector over DDS (rt/<namespace>/haptic/sensed), renders it with the
// kNN renderer in the 1 kHz loop and drives the 3-servo platform through its
// Maestro (dds/operator_loop.hpp), retracting when the stream stops or goes
// stale or DDS declares its publisher gone (liveliness lease), until
// SIGINT/SIGTERM or --duration. It follows one writer of the stream (the
// first, or the one announcing --sensor; dds/writer_follower.hpp), names it
// on stderr and counts what other writers sent.
#include <csignal>
#include <cstdio>

#include "command.hpp"
#include "dds/operator_loop.hpp"
#include "dds_command.hpp"
#include "devices/servo_platform.hpp"
#include "haptics/tactile_dataset.hpp"

namespace onetip::tools {
namespace {

dds::OperatorLoop* g_loop = nullptr;
extern "C" void stopTeleop(int) {
  if (g_loop) g_loop->stop();  // an atomic store: async-signal-safe
}

int runTeleop(const Args& args) {
  const dds::DdsOptions dds_options = ddsOptionsFromArgs(args);
  const std::string sensor = args.optional("sensor").value_or("");
  if (!sensor.empty()) dds::validateSensorName(sensor, "--sensor");
  dds::OperatorLoopOptions o;
  o.neighbors = args.getInt("neighbors", o.neighbors);
  o.stale_s = args.getDouble("stale-ms", o.stale_s * 1e3) * 1e-3;
  o.rate_hz = args.getDouble("rate-hz", o.rate_hz);
  o.validate();
  devices::ServoPlatformOptions servo;
  servo.serial.port = args.get("port");
  servo.validate();

  const haptics::TactileDataset dataset = haptics::loadDataset(args.get("dataset"));
  const haptics::KnnRenderer renderer(dataset);
  dds::Participant participant(dds_options);
  dds::SensedVectorSubscriber input(participant, sensor);
  input.follower().locked = [](const dds::FollowedWriter& w) {  // once, from the loop thread
    std::fprintf(stderr, "teleop: following writer %s (sensor '%s'); samples of any other writer are ignored\n",
                 w.guid.c_str(), w.sensor.c_str());
  };
  devices::ServoPlatform platform(servo);
  platform.open();
  dds::OperatorLoop loop(input, renderer, platform, o);

  g_loop = &loop;
  struct sigaction sa {}, old_int {}, old_term {};
  sa.sa_handler = stopTeleop;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &old_int);
  sigaction(SIGTERM, &sa, &old_term);
  std::fprintf(stderr, "teleop: %zu rows x %d channels; listening on domain %d, %s\n", dataset.size(),
               dataset.channels, dds_options.domain, participant.topic("haptic/sensed").c_str());
  const dds::OperatorLoopStats s = loop.run(args.getDouble("duration", 0));
  sigaction(SIGINT, &old_int, nullptr);
  sigaction(SIGTERM, &old_term, nullptr);
  g_loop = nullptr;
  platform.close();  // retracts
  const dds::FollowedWriter followed = input.follower().followed();
  std::fprintf(stderr, "teleop: followed writer %s (sensor '%s'); ignored %llu samples of other writers\n",
               followed.guid.empty() ? "none" : followed.guid.c_str(), followed.sensor.c_str(),
               static_cast<unsigned long long>(s.ignored));

  std::printf("received %llu sensed vectors (%llu refused), rendered %llu, %llu stalls (%llu: publisher gone), "
              "%llu commands; loop %s, %.3f %% deadlines missed\n",
              static_cast<unsigned long long>(s.received), static_cast<unsigned long long>(s.refused),
              static_cast<unsigned long long>(s.rendered), static_cast<unsigned long long>(s.stalls),
              static_cast<unsigned long long>(s.writers_lost), static_cast<unsigned long long>(s.commands),
              haptics::toString(s.loop.policy).c_str(), s.loop.missedPercent());
  std::printf("sample arrival to device command: median %.3f ms, p99 %.3f ms, max %.3f ms (%lld samples)\n",
              s.sample_to_command.median_ms, s.sample_to_command.p99_ms, s.sample_to_command.max_ms,
              static_cast<long long>(s.sample_to_command.count));
  return 0;
}

std::vector<OptionSpec> teleopOptions() {
  std::vector<OptionSpec> o{{"dataset", "tactile dataset (CSV m1,m2,m3,s1..sN or binary) matching the remote sensor", false, true},
                            {"port", "serial port of the platform's Maestro (e.g. /dev/ttyACM0)", false, true},
                            {"neighbors", "kNN neighbours (default 4)", false, false},
                            {"stale-ms", "retract when no sensed vector came for this long (default 100)", false, false},
                            {"rate-hz", "display loop rate (default 1000)", false, false},
                            {"duration", "seconds to run (default: until interrupted)", false, false},
                            {"sensor", "follow the writer of haptic/sensed announcing this sensor name (publish "
                                       "--sensor; default: the first writer whose sample arrives); others are ignored",
                             false, false}};
  for (auto& s : ddsOptionSpecs()) o.push_back(s);
  return o;
}

const CommandRegistrar reg{{"teleop",
                            "Operator side of teleoperation: render a remote sensed vector received over DDS with the "
                            "kNN renderer at 1 kHz and drive the 3-servo platform, retracting when the stream stalls.",
                            teleopOptions(), runTeleop}};

}  // namespace
}  // namespace onetip::tools
