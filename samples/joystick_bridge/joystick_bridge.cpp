// Joystick bridge: the fingertip as an in-process game controller. Each frame
// the 6-D input becomes six joystick axes in [-32767, 32767] and a trigger,
// scaled exactly like the `onetip joystick` uinput device (onetip/joystick_axes.hpp),
// so a game can read the sensor directly or through /dev/input alike.
// The game loop polls (non-blocking) at its own rate and keeps the latest state.
// Usage: onetip_joystick_bridge [SOURCE] [CALIB PATTERN]   (default: sim:samples/scenarios/sweep_x.yaml)
#include <onetip/onetip.hpp>

#include <cstdio>
#include <string>
#include <thread>

struct GamepadState {
  std::array<std::int32_t, 6> axes = onetip::joystickAxes({});  // x y z rx ry rz at rest
  bool trigger = false;
};

int main(int argc, char** argv) {
  const std::string source = argc > 1 ? argv[1] : "sim:" ONETIP_SOURCE_DIR "/samples/scenarios/sweep_x.yaml";
  if (argc == 3 || argc > 4 || (argc > 1 && argv[1][0] == '-')) {  // a calibration needs its pattern too
    std::fprintf(stderr, "usage: %s [SOURCE [CALIB PATTERN]]   (default SOURCE: sim:samples/scenarios/sweep_x.yaml)\n",
                 argv[0]);
    return 2;
  }
  try {
    onetip::Sensor sensor(onetip::SensorConfig(source, argc > 3 ? argv[2] : "", argc > 3 ? argv[3] : ""));
    sensor.start();
    GamepadState pad;
    int tick = 0;
    for (bool more = true; more;) {
      more = sensor.running();  // one last drain after the source ended
      onetip::Event e;
      while (sensor.pollEvent(e)) {  // drain what arrived since the last tick
        if (e.type == onetip::EventType::input || e.type == onetip::EventType::contact_end)
          pad.axes = onetip::joystickAxes(e.input);
        if (e.type == onetip::EventType::press) pad.trigger = true;
        if (e.type == onetip::EventType::release || e.type == onetip::EventType::contact_end) pad.trigger = false;
        if (e.type == onetip::EventType::error) std::fprintf(stderr, "sensor: %s\n", e.message.c_str());
      }
      if (tick++ % 6 == 0)  // print at 10 Hz
        std::printf("X %6d Y %6d Z %6d RX %6d RY %6d RZ %6d  trigger %d\n", pad.axes[0], pad.axes[1], pad.axes[2],
                    pad.axes[3], pad.axes[4], pad.axes[5], pad.trigger ? 1 : 0);
      std::this_thread::sleep_for(std::chrono::milliseconds(16));  // a 60 Hz game loop
    }
    return 0;
  } catch (const onetip::Error& e) {
    std::fprintf(stderr, "joystick_bridge: %s\n", e.what());
    return 2;
  }
}
