// Consumer of an installed onetip: plays a scenario through the public API and
// checks that the finger's press shows up in the ground truth it receives.
#include <onetip/simulated_sensor.hpp>
#include <onetip/version.hpp>

#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: consumer SCENARIO.yaml\n");
    return 2;
  }
  std::printf("onetip %s\n", onetip::versionString());
  onetip::SimulatedSensorOptions options;
  options.render = false;
  onetip::SimulatedSensor sensor(argv[1], options);
  onetip::SimulatedFrame frame;
  double max_dz = 0;
  int contact_frames = 0;
  while (sensor.next(frame)) {
    contact_frames += frame.contact ? 1 : 0;
    if (frame.truth.dz > max_dz) max_dz = frame.truth.dz;
  }
  std::printf("%d frames in contact, deepest press %.3f mm\n", contact_frames, max_dz);
  return contact_frames > 0 && max_dz > 1.0 ? 0 : 1;
}
