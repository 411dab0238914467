// The paper's turret example: a joystick drives the tank, the fingertip aims
// the turret and a press fires. Everything is simulated: the joystick is a
// scripted stick (the tank drives along x), the fingertip is the simulated
// sensor playing a scenario.
//
// Aim (rate control, degrees): while touching, the turret turns at
// k_rate * yaw deg/s around the vertical and tilts the barrel at
// k_rate * pitch deg/s (clamped to [0, 60] deg elevation); a press fires one
// shell. Ballistics: muzzle speed v, gravity g, flat ground; the shell lands
// at range v^2 sin(2 elevation) / g along the turret's heading from the tank.
// A target sits at (60, 25) m; a shell within 5 m of it is a hit. The press
// threshold is lowered to 0.8 mm (SensorOptions::press_mm) for a light trigger.
// Usage: onetip_turret [SOURCE [CALIB PATTERN]]   (default: sim:samples/scenarios/demo_touch.yaml)
#include <onetip/onetip.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace {

constexpr double kDeg = M_PI / 180;

struct Tank {
  double x = 0, y = 0;            // m
  double heading_deg = 20;        // turret heading, from +x towards +y
  double elevation_deg = 30;      // barrel elevation
};

// The scripted joystick: forward/backward along x, +-5 m/s.
double stickSpeed(double t) { return 5 * std::sin(0.8 * t); }

}  // namespace

int main(int argc, char** argv) {
  const std::string source = argc > 1 ? argv[1] : "sim:" ONETIP_SOURCE_DIR "/samples/scenarios/demo_touch.yaml";
  if (argc == 3 || argc > 4 || (argc > 1 && argv[1][0] == '-')) {  // a calibration needs its pattern too
    std::fprintf(stderr,
                 "usage: %s [SOURCE [CALIB PATTERN]]   (default SOURCE: sim:samples/scenarios/demo_touch.yaml)\n",
                 argv[0]);
    return 2;
  }
  const double k_rate = 3, muzzle_speed = 30, g = 9.81, target_x = 60, target_y = 25;
  try {
    onetip::SensorOptions options;
    options.press_mm = 0.8;  // a light press fires (the default button needs 1.5 mm)
    options.release_mm = 0.5;
    onetip::Sensor sensor(onetip::SensorConfig(source, argc > 3 ? argv[2] : "", argc > 3 ? argv[3] : ""), options);
    Tank tank;
    double last_t = 0;
    bool have_t = false, touching = false;
    onetip::Input6 aim;
    int shots = 0, hits = 0;
    // Every frame result advances the game clock (the sensor's frame time).
    sensor.onFrame([&](const onetip::FrameResult& f) {
      const double dt = have_t ? f.t - last_t : 0;
      last_t = f.t, have_t = true;
      tank.x += stickSpeed(f.t) * dt;
      touching = f.contact;
      aim = f.input;
      if (touching) {
        tank.heading_deg += k_rate * aim.yaw * dt;
        tank.elevation_deg = std::clamp(tank.elevation_deg + k_rate * aim.pitch * dt, 0.0, 60.0);
      }
    });
    sensor.onEvent([&](const onetip::Event& e) {
      if (e.type != onetip::EventType::press) return;
      const double range = muzzle_speed * muzzle_speed * std::sin(2 * tank.elevation_deg * kDeg) / g;
      const double hx = tank.x + range * std::cos(tank.heading_deg * kDeg);
      const double hy = tank.y + range * std::sin(tank.heading_deg * kDeg);
      const bool hit = std::hypot(hx - target_x, hy - target_y) < 5;
      ++shots, hits += hit ? 1 : 0;
      std::printf("t %5.2f s  FIRE from x %6.1f m, heading %5.1f deg, elevation %4.1f deg -> lands (%5.1f, %5.1f) m %s\n",
                  e.t, tank.x, tank.heading_deg, tank.elevation_deg, hx, hy, hit ? "HIT" : "miss");
    });
    sensor.start();
    sensor.waitFinished();
    std::printf("%d shot(s), %d hit(s); tank ended at x %.1f m, turret heading %.1f deg, elevation %.1f deg\n", shots,
                hits, tank.x, tank.heading_deg, tank.elevation_deg);
    return 0;
  } catch (const onetip::Error& e) {
    std::fprintf(stderr, "turret: %s\n", e.what());
    return 2;
  }
}
