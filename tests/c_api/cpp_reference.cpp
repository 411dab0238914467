// The C++ API's answer for the C ABI test: runs a scenario through
// onetip::Sensor (lossless, every frame) and writes every event as a CSV row
//   frame,type,dx,dy,dz,yaw,pitch,roll,sd_dx,sd_dy,sd_dz,sd_yaw,sd_pitch,sd_roll
// (%.17g, so the C side can compare exactly). Usage: cpp_reference SRC OUT.csv
#include <cstdio>
#include <onetip/sensor.hpp>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: cpp_reference SRC OUT.csv\n");
    return 2;
  }
  try {
    onetip::SensorOptions options;
    options.lossless = true;
    options.event_queue_capacity = 100000;
    onetip::Sensor sensor(onetip::SensorConfig(argv[1], "", "", ""), options);
    sensor.start();
    sensor.waitFinished();
    std::FILE* out = std::fopen(argv[2], "w");
    if (!out) return 1;
    std::fprintf(out, "frame,type,dx,dy,dz,yaw,pitch,roll,sd_dx,sd_dy,sd_dz,sd_yaw,sd_pitch,sd_roll\n");
    onetip::Event e;
    while (sensor.pollEvent(e)) {
      std::fprintf(out, "%lld,%d", static_cast<long long>(e.frame), static_cast<int>(e.type));
      for (const onetip::Input6& v : {e.input, e.sd})
        for (double x : v.asArray()) std::fprintf(out, ",%.17g", x);
      std::fprintf(out, "\n");
    }
    return std::fclose(out) == 0 ? 0 : 1;
  } catch (const onetip::Error& e) {
    std::fprintf(stderr, "cpp_reference: %s\n", e.what());
    return 1;
  }
}
