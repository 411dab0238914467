// Consumer of an installed onetip: plays a scenario through the public API and
// checks that the finger's press shows up in the ground truth it receives, then
// runs the same scenario through onetip::Sensor (the pipeline) and checks the
// contact begins, gives 6-D input with a press depth near the truth's, and ends.
#include <onetip/onetip.hpp>

#include <cmath>
#include <cstdio>
#include <string>

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
  if (contact_frames == 0 || max_dz <= 1.0) return 1;

  onetip::SensorOptions sensor_options;
  sensor_options.lossless = true;
  sensor_options.event_queue_capacity = 100000;
  onetip::Sensor pipeline(onetip::SensorConfig(std::string("sim:") + argv[1]), sensor_options);
  pipeline.start();
  pipeline.waitFinished();
  int begins = 0, inputs = 0, ends = 0;
  double measured_max_dz = 0;
  onetip::Event e;
  while (pipeline.pollEvent(e)) {
    begins += e.type == onetip::EventType::contact_begin;
    ends += e.type == onetip::EventType::contact_end;
    if (e.type == onetip::EventType::input) {
      ++inputs;
      if (e.input.dz > measured_max_dz) measured_max_dz = e.input.dz;
    }
  }
  std::printf("pipeline: %d contact begin, %d input, %d contact end events; deepest measured press %.3f mm\n", begins,
              inputs, ends, measured_max_dz);
  return begins >= 1 && inputs > 10 && ends >= 1 && std::abs(measured_max_dz - max_dz) < 0.5 ? 0 : 1;
}
