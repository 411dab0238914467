// The 3-DoF wire device's geometry (Eq. 2.3-2.9), force controller (Eq. 2.11)
// against a simulated plant with motor lag and sensor noise, and the
// magnetometer offset calibration (Eq. 2.12).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "core/error.hpp"
#include "core/rotation.hpp"
#include "devices/imu_orientation.hpp"
#include "devices/wire_device.hpp"
#include "devices/wire_force_controller.hpp"
#include "wire_plant.hpp"

namespace onetip::devices {
namespace {

TEST(WireDeviceGeometry, RestIsUnloadedAndEqualTensionsPushStraightUp) {
  const WireDeviceGeometry g;
  const WireConfiguration rest = wireConfiguration(g, Eigen::Matrix3d::Identity(), 0.0);
  EXPECT_LT(rest.x.norm(), 1e-12);
  // Cable i from plate vertex (7 mm radius, z = -14) to body vertex (14 mm, z = 0):
  // 7 mm outwards and 14 mm up.
  const double slant = std::atan2(7.0, 14.0);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(rest.G(2, i), std::cos(slant), 1e-12);
  const Eigen::Vector3d f = rest.G * Eigen::Vector3d(0.5, 0.5, 0.5);
  EXPECT_NEAR(f.head<2>().norm(), 0.0, 1e-12);
  EXPECT_NEAR(f.z(), 1.5 * std::cos(slant), 1e-12);
  // Lifting the plate by hz compresses the springs by about hz cos(slant).
  const WireConfiguration lifted = wireConfiguration(g, Eigen::Matrix3d::Identity(), 0.1);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(lifted.x(i), 0.1 * std::cos(slant), 2e-3);
  EXPECT_DOUBLE_EQ(g.deformationFromForce(0.5 * 4.0), 2.0);  // k_f = 0.5: 2 N at 2 mm
}

struct Trace {
  std::vector<double> t, value;
};

TEST(WireForceController, StepOf08NewtonMeetsTheThesisRiseTimeWithoutOvershoot) {
  const WireDeviceGeometry g;
  WireForceController controller(g);
  testing::WirePlant plant(g);
  const double dt = 1.0 / 200.0, t_step = 0.1, target = 0.8;
  Trace trace;
  for (double t = 0.0; t < 2.0; t += dt) {
    const Eigen::Vector3d fd(0.0, 0.0, t >= t_step ? target : 0.0);
    plant.advance(controller.step(fd, plant.measuredRotation(), plant.measuredFsr(), dt), dt);
    trace.t.push_back(t + dt);
    trace.value.push_back(plant.normalForce());
  }
  double t10 = -1, t90 = -1, peak = 0, steady = 0;
  int n_steady = 0;
  for (size_t i = 0; i < trace.t.size(); ++i) {
    if (t10 < 0 && trace.value[i] >= 0.1 * target) t10 = trace.t[i];
    if (t90 < 0 && trace.value[i] >= 0.9 * target) t90 = trace.t[i];
    peak = std::max(peak, trace.value[i]);
    if (trace.t[i] > 1.5) {
      steady += trace.value[i];
      ++n_steady;
    }
  }
  steady /= n_steady;
  const double rise = t90 - t10, overshoot = 100.0 * (peak - target) / target;
  std::printf("wire force step 0.8 N: rise time %.3f s, overshoot %.2f %%, steady-state %.4f N\n", rise, overshoot,
              steady);
  ASSERT_GT(t10, 0.0);
  ASSERT_GT(t90, 0.0);
  EXPECT_NEAR(rise, 0.2, 0.05);
  EXPECT_LT(overshoot, 10.0);
  EXPECT_NEAR(steady, target, 0.02);
}

// Directional force references: fd = F n(roll_ref, pitch_ref), n = Ry(roll) Rx(pitch) e_z.
void trackSinusoid(bool roll_axis, double& rms_force_dir_deg, double& rms_plate_deg, double& rms_normal_n) {
  const WireDeviceGeometry g;
  WireForceController controller(g);
  testing::WirePlant plant(g);
  const double dt = 1.0 / 200.0, F = 0.6, amplitude = 10.0, freq = 0.5;
  double sum_dir = 0, sum_plate = 0, sum_normal = 0;
  int n = 0;
  for (double t = 0.0; t < 5.0; t += dt) {
    const double ref = amplitude * std::sin(2.0 * M_PI * freq * t);
    const double roll = roll_axis ? ref : 0.0, pitch = roll_axis ? 0.0 : ref;
    const Eigen::Vector3d fd = F * (rotationFromYawPitchRoll(0.0, pitch * kRadPerDeg, roll * kRadPerDeg) * Eigen::Vector3d::UnitZ());
    plant.advance(controller.step(fd, plant.measuredRotation(), plant.measuredFsr(), dt), dt);
    if (t < 1.0) continue;
    const Eigen::Vector3d f = plant.contactForce();
    const double f_roll = std::atan2(f.x(), f.z()) * kDegPerRad, f_pitch = -std::asin(f.y() / f.norm()) * kDegPerRad;
    const double dir_error = roll_axis ? f_roll - ref : f_pitch - ref;
    const double plate_error = roll_axis ? plant.rollDeg() - ref : plant.pitchDeg() - ref;
    sum_dir += dir_error * dir_error;
    sum_plate += plate_error * plate_error;
    sum_normal += (f.norm() - F) * (f.norm() - F);
    ++n;
  }
  rms_force_dir_deg = std::sqrt(sum_dir / n);
  rms_plate_deg = std::sqrt(sum_plate / n);
  rms_normal_n = std::sqrt(sum_normal / n);
}

TEST(WireForceController, TracksSinusoidalRollAndPitchReferences) {
  for (bool roll_axis : {true, false}) {
    double dir = 0, plate = 0, normal = 0;
    trackSinusoid(roll_axis, dir, plate, normal);
    std::printf("%s 10 deg at 0.5 Hz: RMS force-direction error %.2f deg, plate tilt error %.2f deg, |f| error %.4f N\n",
                roll_axis ? "roll " : "pitch", dir, plate, normal);
    // With fd' neglected (as in the thesis) the force follows a first-order lag
    // 1 / (1 + j w / lambda): RMS error A (w / lambda) / sqrt(1 + (w / lambda)^2) / sqrt(2).
    const double r = 2.0 * M_PI * 0.5 / 11.0;
    const double first_order = 10.0 * r / std::sqrt(1.0 + r * r) / std::sqrt(2.0);
    EXPECT_LT(dir, 1.25 * first_order);
    EXPECT_GT(dir, 0.8 * first_order);
    EXPECT_LT(normal, 0.03);
    // The plate's own tilt (reported) is small: the fingertip's rotational stiffness takes the moment.
  }
}

TEST(WireDevice, DesiredForcesAreLimitedToWhatTheDeviceCanDisplay) {
  Eigen::Vector3d f = limitWireForce({0.0, 0.0, 3.0}, 1.0, 20.0);
  EXPECT_DOUBLE_EQ(f.z(), 1.0);
  f = limitWireForce({1.0, 0.0, 0.5}, 1.0, 20.0);
  EXPECT_NEAR(std::atan2(f.x(), f.z()) * kDegPerRad, 20.0, 1e-9);
  f = limitWireForce({0.3, 0.3, -1.0}, 1.0, 20.0);
  EXPECT_LT(f.norm(), 1e-12);  // pulling away from the finger cannot be displayed
}

TEST(ImuOrientation, RecoversTheRotationFromGravityAndField) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(-0.5, 0.5), yaw(-M_PI, M_PI);
  const Eigen::Vector3d up(0, 0, 1), field(20.0, 0.0, -40.0);
  for (int k = 0; k < 20; ++k) {
    const Eigen::Matrix3d R = rotationFromYawPitchRoll(yaw(rng), angle(rng), angle(rng));
    const Eigen::Matrix3d est = orientationFromAccelMag(R.transpose() * up, R.transpose() * field);
    EXPECT_LT((est - R).norm(), 1e-9);
  }
}

TEST(MagnetometerOffsetCalibration, Eq212RemovesTheMotorsFieldFromTheHeading) {
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 0.3);  // uT
  std::uniform_real_distribution<double> tilt(-0.4, 0.4), yaw(-M_PI, M_PI);
  const Eigen::Vector3d up(0, 0, 1), field(20.0, 0.0, -40.0), motors(12.0, -9.0, 20.0);
  auto noisy = [&](const Eigen::Vector3d& v) { return Eigen::Vector3d(v.x() + noise(rng), v.y() + noise(rng), v.z() + noise(rng)); };
  MagnetometerOffsetCalibration calibration;
  for (int posture = 0; posture < 10; ++posture) {
    const Eigen::Matrix3d R = rotationFromYawPitchRoll(yaw(rng), tilt(rng), tilt(rng));
    for (int trial = 0; trial < 5; ++trial)
      calibration.add(noisy(R.transpose() * field + motors), noisy(R.transpose() * field));
  }
  ASSERT_EQ(calibration.samples(), 50u);
  const Eigen::Vector3d offset = calibration.offset();
  EXPECT_LT((offset - motors).norm(), 0.25);
  double raw = 0, fixed = 0;
  int n = 0;
  for (double psi = -170.0; psi <= 180.0; psi += 10.0, ++n) {
    const Eigen::Matrix3d R = rotationFromYawPitchRoll(psi * kRadPerDeg, 0.0, 0.0);
    const Eigen::Vector3d m = noisy(R.transpose() * field + motors);
    auto yawError = [&](const Eigen::Vector3d& mag) {
      const Eigen::Matrix3d est = orientationFromAccelMag(R.transpose() * up, mag);
      return std::remainder(std::atan2(est(1, 0), est(0, 0)) * kDegPerRad - psi, 360.0);
    };
    raw += std::pow(yawError(m), 2);
    fixed += std::pow(yawError(m - offset), 2);
  }
  raw = std::sqrt(raw / n);
  fixed = std::sqrt(fixed / n);
  std::printf("yaw RMS error: %.2f deg uncalibrated, %.2f deg with the Eq. 2.12 offset\n", raw, fixed);
  EXPECT_GT(raw, 20.0);
  EXPECT_LT(fixed, 2.0);
  EXPECT_THROW(MagnetometerOffsetCalibration{}.offset(), InputError);
}

}  // namespace
}  // namespace onetip::devices
