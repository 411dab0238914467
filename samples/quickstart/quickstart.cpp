// Quickstart: the simulated fingertip sensor, its 6-D input events printed.
// Usage: onetip_quickstart [SCENARIO.yaml]   (default: samples/scenarios/press.yaml)
#include <onetip/sensor.hpp>

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  if (argc > 2 || (argc > 1 && argv[1][0] == '-')) {
    std::fprintf(stderr, "usage: %s [SCENARIO.yaml]   (default: samples/scenarios/press.yaml)\n", argv[0]);
    return 2;
  }
  const std::string scenario = argc > 1 ? argv[1] : ONETIP_SOURCE_DIR "/samples/scenarios/press.yaml";
  try {
    // sim: sources bring their own calibration and pattern
    onetip::Sensor sensor(onetip::SensorConfig("sim:" + scenario));
    int inputs = 0;
    sensor.onEvent([&](const onetip::Event& e) {  // runs on the sensor's processing thread
      if (e.type == onetip::EventType::input) ++inputs;
      if (e.type == onetip::EventType::error) {  // e.g. a press past the working range: says what happened
        std::printf("frame %3lld error         %s\n", static_cast<long long>(e.frame), e.message.c_str());
        return;
      }
      const onetip::Input6& v = e.input;
      std::printf("frame %3lld %-13s dx %6.2f dy %6.2f dz %6.2f mm  yaw %6.1f pitch %6.1f roll %6.1f deg\n",
                  static_cast<long long>(e.frame), std::string(toString(e.type)).c_str(), v.dx, v.dy, v.dz, v.yaw,
                  v.pitch, v.roll);
    });
    sensor.start();
    sensor.waitFinished();  // until the scenario ends
    return inputs > 0 ? 0 : 1;
  } catch (const onetip::Error& e) {
    std::fprintf(stderr, "quickstart: %s\n", e.what());
    return 2;
  }
}
