// Teleoperation sample, operator side (process 2 of 2): subscribes to the
// remote sensed vector over DDS (see remote.cpp), renders it with the kNN
// renderer (4 neighbours, dataset simulated on a 9 deg grid) in the 1 kHz
// loop (dds/operator_loop.hpp) and drives the 3-servo cable platform, whose
// Maestro is emulated on a pseudo-terminal (the emulator of tests/unit/devices,
// so no hardware is needed). When the stream stops or stalls for 100 ms the
// platform retracts; when it comes back the servos move from rest at their
// speed limit. Prints, four times a second, the targets the Maestro received.
// Usage: onetip_teleop_local [seconds] [domain] [interface] [peer]
#include <atomic>
#include <cstdio>
#include <map>
#include <thread>

#include "dds/operator_loop.hpp"
#include "devices/servo_platform.hpp"
#include "haptics/biotac_like_sensor.hpp"
#include "haptics/display_grid.hpp"
#include "maestro_emulator.hpp"

using namespace onetip;

int main(int argc, char** argv) try {
  const double seconds = argc > 1 ? std::stod(argv[1]) : 15.0;
  dds::DdsOptions net;
  net.domain = argc > 2 ? std::stoi(argv[2]) : 0;
  net.interface = argc > 3 ? argv[3] : "lo";
  net.peers = {argc > 4 ? argv[4] : "127.0.0.1"};

  std::printf("building the renderer's dataset (9 deg grid)...\n");
  const haptics::TactileDataset dataset =
      haptics::simulateDataset(haptics::PlatformKinematics{}, haptics::BiotacLikeSensor{}, 9.0);
  const haptics::KnnRenderer renderer(dataset);
  devices::testing::MaestroEmulator maestro;  // the device, on a pty
  devices::ServoPlatformOptions options;
  options.serial.port = maestro.path();
  devices::ServoPlatform platform(options);
  platform.open();

  dds::Participant participant(net);
  dds::SensedVectorSubscriber input(participant);
  dds::OperatorLoop loop(input, renderer, platform);
  std::printf("listening on %s (domain %d) for %.0f s\n", participant.topic("haptic/sensed").c_str(), net.domain, seconds);
  std::printf("%7s | %22s | %s\n", "time s", "sent to servos deg", "state");

  std::atomic<bool> done{false};
  std::thread printer([&] {
    const auto start = std::chrono::steady_clock::now();
    while (!done) {
      std::this_thread::sleep_for(std::chrono::milliseconds(250));
      std::map<int, double> sent;
      for (const auto& e : maestro.events(0x84)) sent[e.channel] = options.calibration[0].degreesFromQuarterMicroseconds(e.value);
      const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::printf("%7.2f | %6.1f %6.1f %6.1f    | %s\n", t, sent[0], sent[1], sent[2],
                  platform.status().retracted ? "retracted" : "rendering");
    }
  });
  const dds::OperatorLoopStats s = loop.run(seconds);
  done = true;
  printer.join();
  platform.close();
  std::printf("received %llu sensed vectors, %llu stalls; loop %s, %.3f %% deadlines missed\n",
              static_cast<unsigned long long>(s.received), static_cast<unsigned long long>(s.stalls),
              haptics::toString(s.loop.policy).c_str(), s.loop.missedPercent());
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "onetip_teleop_local: %s\n", e.what());
  return 1;
}
