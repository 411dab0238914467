// Teleoperation sample, remote side (process 1 of 2): a fingertip sensor on
// the robot touched by a plate. The simulator plays a plate scenario (default
// samples/scenarios/back_flat_back.yaml) in real time; each frame's plate pose
// (sensor frame S) is mapped to the display frame D (x_D = x_S, y_D = -y_S,
// z_D = -z_S: the pad faces down onto the plate), felt by a BioTac-like sensor
// model (20 channels, counts) and published over DDS on
// rt/<namespace>/haptic/sensed (onetip_msgs/SensedVector, docs/dds/README.md).
// The operator side is `onetip_teleop_local` (or `onetip teleop` with a real
// platform). By default both use the loopback only; across two machines give
// each its interface and the other's address.
// Usage: onetip_teleop_remote [SCENARIO.yaml] [domain] [interface] [peer]
#include <Eigen/Geometry>
#include <chrono>
#include <cstdio>
#include <thread>

#include "dds/sensed_vector_link.hpp"
#include "haptics/biotac_like_sensor.hpp"
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

}  // namespace

int main(int argc, char** argv) try {
  const std::string scenario_path = argc > 1 ? argv[1] : ONETIP_SOURCE_DIR "/samples/scenarios/back_flat_back.yaml";
  dds::DdsOptions net;
  net.domain = argc > 2 ? std::stoi(argv[2]) : 0;
  net.interface = argc > 3 ? argv[3] : "lo";
  net.peers = {argc > 4 ? argv[4] : "127.0.0.1"};

  sim::Simulator remote(sim::loadScenario(scenario_path));
  const haptics::BiotacLikeSensor sensor;
  dds::Participant participant(net);
  dds::SensedVectorPublisher publisher(participant, "biotac_like");
  std::printf("%s: %d frames at %.0f fps; waiting for the operator on %s (domain %d)...\n", scenario_path.c_str(),
              remote.frameCount(), remote.scenario().fps, participant.topic("haptic/sensed").c_str(), net.domain);
  const auto give_up = Clock::now() + std::chrono::seconds(30);
  while (publisher.matchedReaders() == 0 && Clock::now() < give_up) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  if (publisher.matchedReaders() == 0) std::printf("no operator after 30 s: publishing anyway\n");

  const auto start = Clock::now();
  while (!remote.done()) {
    const sim::GroundTruthFrame& gt = remote.next();
    std::this_thread::sleep_until(start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(gt.t)));
    const std::vector<double> sensed = sensor.sense(plateInDisplayFrame(gt.indenter_poses.at(0)));
    const auto n = publisher.publish(gt.t, sensed);
    if (n % 10 == 1) std::printf("t %6.3f s  sample %4llu  p_dc %6.0f counts\n", gt.t, static_cast<unsigned long long>(n), sensed.back());
  }
  std::printf("scenario done; the operator's display retracts when the stream stops\n");
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "onetip_teleop_remote: %s\n", e.what());
  return 1;
}
