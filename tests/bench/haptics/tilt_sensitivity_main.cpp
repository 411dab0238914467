// haptic_tilt_sensitivity: how much Eq. 9 error a small platform tilt costs the
// BioTac-like model, to set beside the journal paper's calibration remark
// (Sec. 3.1: its best e_f of ~2.0 "corresponds to a platform orientation error
// of approximately 2.75 deg"). For flat presses (all servos at one angle) the
// plate is turned by the tilt about eight horizontal axes through its centre;
// e_f = mean over channels of |s_tilted - s| / sigma_i (sigma_i over the 3-deg
// dataset, as in the evaluation), averaged over the eight axes. Noise-free.
// usage: haptic_tilt_sensitivity [tilt_deg]
#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/rotation.hpp"
#include "haptics/biotac_like_sensor.hpp"
#include "haptics/channel_scaling.hpp"
#include "haptics/display_grid.hpp"

using namespace onetip;
using namespace onetip::haptics;

int main(int argc, char** argv) {
  const double tilt_deg = argc > 1 ? std::stod(argv[1]) : 2.75;
  const PlatformKinematics device;
  const BiotacLikeSensor sensor;
  const ChannelScaling scaling = ChannelScaling::fromDataset(simulateDataset(device, sensor, 3.0));
  std::printf("servo_deg,press_mm,e_f_tilt\n");
  for (double angle = 90.0; angle <= 190.0; angle += 20.0) {
    const PlatformPose pose = device.forward({angle, angle, angle});
    const auto nominal = sensor.sense(pose.plane);
    double total = 0.0;
    for (int a = 0; a < 8; ++a) {
      const Eigen::Vector3d axis(std::cos(a * M_PI / 4), std::sin(a * M_PI / 4), 0.0);
      ContactPlane tilted = pose.plane;
      tilted.normal = Eigen::AngleAxisd(tilt_deg * kRadPerDeg, axis) * tilted.normal;
      total += scaling.meanStandardizedError(sensor.sense(tilted).data(), nominal.data()) / 8.0;
    }
    std::printf("%.0f,%.2f,%.3f\n", angle, pose.z_mm, total);
  }
  return 0;
}
