// 6-DoF object manipulation: the fingertip moves and turns a virtual cube.
//
// Position control with clutching: while the finger touches, the cube's pose
// is its pose at contact onset followed by the finger's motion since then
// (the 6-D input, docs/reference.md: translation [dx, dy, -dz] in S scaled by
// `gain_mm` and rotation R = Rz(yaw) * Ry(roll) * Rx(pitch)); lifting the
// finger leaves the cube where it is, and the next touch continues from there.
// At each contact end the cube is drawn as ASCII (a view along -z of S, x to the
// right, y up) and its pose printed. Angles in degrees, lengths in mm.
// Usage: onetip_object_manipulation [SOURCE [CALIB PATTERN]]   (default: sim:samples/scenarios/demo_touch.yaml)
#include <onetip/onetip.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

namespace {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<Vec3, 3>;

Mat3 mul(const Mat3& a, const Mat3& b) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r[i][j] += a[i][k] * b[k][j];
  return r;
}
Vec3 apply(const Mat3& m, const Vec3& v) {
  return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
          m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}
// R = Rz(yaw) * Ry(roll) * Rx(pitch), degrees.
Mat3 rotation(const onetip::Input6& v) {
  const double d = M_PI / 180, cz = std::cos(v.yaw * d), sz = std::sin(v.yaw * d), cy = std::cos(v.roll * d),
               sy = std::sin(v.roll * d), cx = std::cos(v.pitch * d), sx = std::sin(v.pitch * d);
  const Mat3 rz{{{cz, -sz, 0}, {sz, cz, 0}, {0, 0, 1}}}, ry{{{cy, 0, sy}, {0, 1, 0}, {-sy, 0, cy}}},
      rx{{{1, 0, 0}, {0, cx, -sx}, {0, sx, cx}}};
  return mul(rz, mul(ry, rx));
}

struct Pose {
  Vec3 position{0, 0, 0};
  Mat3 rotation{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
};

// The finger's motion applied after the pose at onset.
Pose moved(const Pose& onset, const onetip::Input6& v, double gain_mm) {
  Pose p;
  p.rotation = mul(rotation(v), onset.rotation);
  const Vec3 t{v.dx * gain_mm, v.dy * gain_mm, -v.dz * gain_mm};
  for (int i = 0; i < 3; ++i) p.position[i] = onset.position[i] + t[i];
  return p;
}

void draw(const Pose& p) {
  constexpr int W = 41, H = 21;
  char grid[H][W + 1];
  for (auto& row : grid) {
    std::fill(row, row + W, '.');
    row[W] = '\0';
  }
  const double half = 4;  // the cube's half side, mm; the view spans +-20 mm
  for (int c = 0; c < 8; ++c) {
    const Vec3 corner = apply(p.rotation, {c & 1 ? half : -half, c & 2 ? half : -half, c & 4 ? half : -half});
    const int col = static_cast<int>(std::lround((p.position[0] + corner[0] + 20) / 40 * (W - 1)));
    const int row = static_cast<int>(std::lround((20 - p.position[1] - corner[1]) / 40 * (H - 1)));
    if (col >= 0 && col < W && row >= 0 && row < H) grid[row][col] = corner[2] + p.position[2] > 0 ? '#' : 'o';
  }
  for (const auto& row : grid) std::printf("  %s\n", row);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string source = argc > 1 ? argv[1] : "sim:" ONETIP_SOURCE_DIR "/samples/scenarios/demo_touch.yaml";
  if (argc == 3 || argc > 4 || (argc > 1 && argv[1][0] == '-')) {  // a calibration needs its pattern too
    std::fprintf(stderr,
                 "usage: %s [SOURCE [CALIB PATTERN]]   (default SOURCE: sim:samples/scenarios/demo_touch.yaml)\n",
                 argv[0]);
    return 2;
  }
  const double gain_mm = 3;  // 1 mm of finger motion moves the cube 3 mm
  try {
    onetip::Sensor sensor(onetip::SensorConfig(source, argc > 3 ? argv[2] : "", argc > 3 ? argv[3] : ""));
    Pose onset, now;
    sensor.start();
    onetip::Event e;
    for (;;) {
      if (!sensor.waitEvent(e, 1.0)) {
        if (!sensor.running()) break;  // the source ended and every event was read
        continue;
      }
      if (e.type == onetip::EventType::contact_begin) onset = now;
      if (e.type == onetip::EventType::input) now = moved(onset, e.input, gain_mm);
      if (e.type == onetip::EventType::contact_end) {
        const auto& r = now.rotation;
        std::printf("contact ended at frame %lld: cube at (%.1f, %.1f, %.1f) mm, yaw %.1f deg\n",
                    static_cast<long long>(e.frame), now.position[0], now.position[1], now.position[2],
                    std::atan2(r[1][0], r[0][0]) * 180 / M_PI);
        draw(now);
      }
    }
    return 0;
  } catch (const onetip::Error& err) {
    std::fprintf(stderr, "object_manipulation: %s\n", err.what());
    return 2;
  }
}
