// Teleoperation sample: a remote fingertip sensor touched by a plate, the kNN
// tactile renderer and the 3-servo cable platform, in one loop with network
// latency and jitter. No hardware: the platform's Maestro is emulated on a
// pseudo-terminal, and the program prints what the device was commanded.
//
//   remote side:  the simulator plays a plate scenario (default
//                 samples/scenarios/back_flat_back.yaml); each frame's plate
//                 pose (sensor frame S) is mapped to the display frame D
//                 (x_D = x_S, y_D = -y_S, z_D = -z_S: the pad faces down onto
//                 the plate) and felt by a BioTac-like sensor model;
//   network:      each sensed vector arrives latency +- jitter ms later;
//   local side:   the kNN renderer (4 neighbours, dataset simulated on a 9 deg
//                 grid) gives servo angles, sent to the ServoPlatform driver,
//                 whose speed limit and watchdog apply. Printed per delivered
//                 sample: remote time, the DC pressure channel (counts), the
//                 rendered angles and the last targets the Maestro received.
// Usage: onetip_teleoperation [SCENARIO.yaml] [latency_ms] [jitter_ms]
#include <Eigen/Geometry>
#include <cstdio>
#include <deque>
#include <random>
#include <thread>

#include "devices/servo_platform.hpp"
#include "haptics/biotac_like_sensor.hpp"
#include "haptics/display_grid.hpp"
#include "haptics/knn_renderer.hpp"
#include "maestro_emulator.hpp"
#include "sim/simulator.hpp"

using namespace onetip;
using Clock = std::chrono::steady_clock;

namespace {

// The scenario's plate (indenter 0) as a ContactPlane in the display frame D.
haptics::ContactPlane plateInDisplayFrame(const Eigen::Isometry3d& plate_in_s) {
  const Eigen::Matrix3d s_to_d = Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal();
  haptics::ContactPlane plane;
  plane.point = s_to_d * plate_in_s.translation();
  plane.normal = s_to_d * (-(plate_in_s.linear() * Eigen::Vector3d::UnitZ()));  // from the plate into the pad
  return plane;
}

struct InFlight {
  Clock::time_point arrives;
  double t;
  std::vector<double> sensed;
};

}  // namespace

int main(int argc, char** argv) try {
  const std::string scenario_path = argc > 1 ? argv[1] : ONETIP_SOURCE_DIR "/samples/scenarios/back_flat_back.yaml";
  const double latency_ms = argc > 2 ? std::stod(argv[2]) : 40.0;
  const double jitter_ms = argc > 3 ? std::stod(argv[3]) : 15.0;

  // Local side: renderer and device.
  const haptics::PlatformKinematics kinematics;
  const haptics::BiotacLikeSensor sensor;
  std::printf("building the renderer's dataset (9 deg grid)...\n");
  const haptics::TactileDataset dataset = haptics::simulateDataset(kinematics, sensor, 9.0);
  const haptics::KnnRenderer renderer(dataset);
  devices::testing::MaestroEmulator maestro;  // the device, on a pty
  devices::ServoPlatformOptions options;
  options.serial.port = maestro.path();
  devices::ServoPlatform platform(options);
  platform.open();

  // Remote side.
  sim::Simulator remote(sim::loadScenario(scenario_path));
  const double fps = remote.scenario().fps;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> jitter(-jitter_ms, jitter_ms);
  std::deque<InFlight> network;
  std::printf("%s: %d frames at %.0f fps, latency %.0f +- %.0f ms\n", scenario_path.c_str(), remote.frameCount(), fps,
              latency_ms, jitter_ms);
  std::printf("%7s %7s | %22s | %22s\n", "t_s", "p_dc", "rendered m1,m2,m3 deg", "sent to servos deg");

  const auto start = Clock::now();
  int frame = 0;
  while (!remote.done() || !network.empty()) {
    const auto now = Clock::now();
    if (!remote.done() && now >= start + std::chrono::duration<double>(frame / fps)) {
      const sim::GroundTruthFrame& gt = remote.next();
      ++frame;
      const auto delay = std::chrono::duration<double, std::milli>(std::max(0.0, latency_ms + jitter(rng)));
      network.push_back({now + std::chrono::duration_cast<Clock::duration>(delay), gt.t,
                         sensor.sense(plateInDisplayFrame(gt.indenter_poses.at(0)))});
    }
    // Deliver what arrived (jitter may reorder: a late packet older than one already used is dropped).
    static double newest = -1.0;
    for (auto it = network.begin(); it != network.end();) {
      if (it->arrives > now) {
        ++it;
        continue;
      }
      if (it->t > newest) {
        newest = it->t;
        const haptics::RenderResult r = renderer.render(it->sensed.data(), 4);
        platform.command(r.command);
        const devices::DeviceStatus status = platform.status();
        std::map<int, double> sent;
        for (const auto& e : maestro.events(0x84)) sent[e.channel] = options.calibration[0].degreesFromQuarterMicroseconds(e.value);
        std::printf("%7.3f %7.0f | %6.1f %6.1f %6.1f    | %6.1f %6.1f %6.1f%s\n", it->t, it->sensed.back(),
                    r.command[0], r.command[1], r.command[2], sent[0], sent[1], sent[2],
                    status.retracted ? "  (retracted)" : "");
      }
      it = network.erase(it);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // input stalls: the watchdog retracts
  const devices::DeviceStatus status = platform.status();
  std::printf("after the stream ended: outputs %.1f %.1f %.1f deg, retracted %s, %llu commands sent\n",
              status.outputs[0], status.outputs[1], status.outputs[2], status.retracted ? "yes" : "no",
              static_cast<unsigned long long>(status.commands_sent));
  platform.close();
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "onetip_teleoperation: %s\n", e.what());
  return 1;
}
