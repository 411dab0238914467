// onetip's pad as the haptic loop's sensor (onetip_contact_sensor.hpp) and the
// PCA feature of its field (contact_field_pca.hpp): frames checked against the
// contact model's conformity condition (under a rigid plate the pressed skin
// moves exactly with it), tilt directions, independence from the sweep order,
// and the PCA against a field of known components.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "core/error.hpp"
#include "haptics/contact_field_pca.hpp"
#include "haptics/onetip_contact_sensor.hpp"

using namespace onetip;
using namespace onetip::haptics;

namespace {
ContactPlane levelPlate(double z_mm) { return {Eigen::Vector3d(0.0, 0.0, z_mm), Eigen::Vector3d::UnitZ()}; }
// A plate through (0, 0, z) rising by `tilt_deg` towards +y (the fingertip) in D.
ContactPlane tiltedTowardsTip(double z_mm, double tilt_deg) {
  const double b = tilt_deg * M_PI / 180.0;
  return {Eigen::Vector3d(0.0, 0.0, z_mm), Eigen::Vector3d(0.0, -std::sin(b), std::cos(b))};
}
}  // namespace

TEST(OnetipSensor, FiveByFiveGridAndFullFieldChannels) {
  const OnetipContactSensor grid;
  EXPECT_EQ(grid.channels(), 75);
  EXPECT_EQ(grid.markers(), (std::vector<int>{0, 4, 8, 12, 16, 68, 72, 76, 80, 84, 136, 140, 144, 148, 152, 204, 208,
                                              212, 216, 220, 272, 276, 280, 284, 288}));
  OnetipSensorOptions o;
  o.marker_stride = 1;
  EXPECT_EQ(OnetipContactSensor(o).channels(), 867);
  o.marker_stride = 0;
  EXPECT_THROW(OnetipContactSensor{o}, InputError);
}

TEST(OnetipSensor, LevelPressMovesTheApexWithThePlate) {
  OnetipSensorOptions o;
  o.marker_stride = 1;
  const OnetipContactSensor sensor(o);
  const int centre = 8 * 17 + 8;
  for (double z : {0.3, 1.0, 2.5}) {
    const auto u = sensor.sense(levelPlate(z));
    // Conformity: the apex node is pressed exactly z into the pad (dz = -z).
    EXPECT_NEAR(u[3 * centre + 2], -z, 1e-9) << z;
    EXPECT_NEAR(u[3 * centre], 0.0, 1e-9);
    EXPECT_NEAR(u[3 * centre + 1], 0.0, 1e-9);
    // The dome is symmetric: opposite corners move alike.
    EXPECT_NEAR(u[2], u[3 * 288 + 2], 1e-9);
  }
  for (double v : sensor.sense(levelPlate(-0.5))) EXPECT_EQ(v, 0.0);
}

TEST(OnetipSensor, PlatePoseFlipsDIntoThePadFrame) {
  const OnetipContactSensor sensor;
  const ContactPlane plate = tiltedTowardsTip(0.8, 15.0);
  const Eigen::Isometry3d pose = sensor.platePose(plate);
  // Local z (away from the pad) is -Rx(180) n = (-n_x, n_y, n_z).
  const Eigen::Vector3d up(-plate.normal.x(), plate.normal.y(), plate.normal.z());
  EXPECT_LT((pose.linear().col(2) - up).norm(), 1e-12);
  // The face contains the plate's point mapped to P: (x, -y, apex - z).
  const Eigen::Vector3d point_p(plate.point.x(), -plate.point.y(), 0.3 - plate.point.z());
  EXPECT_NEAR((pose.translation() - point_p).dot(up), 0.0, 1e-12);
  EXPECT_NEAR(pose.translation().x(), 0.0, 1e-12);
  EXPECT_NEAR(pose.translation().y(), 0.0, 1e-12);
  EXPECT_THROW(sensor.platePose({Eigen::Vector3d::Zero(), -Eigen::Vector3d::UnitZ()}), InputError);
}

TEST(OnetipSensor, TiltTowardsTheTipPressesTheLowRowsHarder) {
  OnetipSensorOptions o;
  o.marker_stride = 1;
  const OnetipContactSensor sensor(o);
  // +y_D (the tip) is -y_P, where rows start (row 0 at the most negative y).
  const auto u = sensor.sense(tiltedTowardsTip(1.0, 10.0));
  const int near_tip = 2 * 17 + 8, far = 14 * 17 + 8;
  EXPECT_LT(u[3 * near_tip + 2], u[3 * far + 2] - 0.5);
}

TEST(OnetipSensor, ReadingsDoNotDependOnTheSweepOrder) {
  const OnetipContactSensor a, b;
  const ContactPlane p = tiltedTowardsTip(1.2, 8.0), q = tiltedTowardsTip(2.0, -12.0);
  const auto first = a.sense(p);
  a.sense(q);  // friction history would stay in the model without a reset
  EXPECT_EQ(a.sense(p), first);
  EXPECT_EQ(b.sense(p), first);
}

TEST(ContactFieldPca, RecoversKnownComponents) {
  // Rows mean + a v1 + b v2 with var(a) = 4 > var(b) = 1 and orthonormal v1, v2.
  const int n = 12;
  Eigen::VectorXd v1 = Eigen::VectorXd::Zero(n), v2 = Eigen::VectorXd::Zero(n), mean(n);
  v1.head(4).setConstant(0.5);
  v2.segment(4, 4).setConstant(0.5);
  for (int i = 0; i < n; ++i) mean(i) = 0.1 * i;
  std::mt19937 rng(3);
  std::normal_distribution<double> g(0.0, 1.0);
  TactileDataset fields;
  fields.channels = n;
  std::vector<std::pair<double, double>> coefficients;
  for (int r = 0; r < 400; ++r) {
    const double a = 2.0 * g(rng), b = g(rng);
    const Eigen::VectorXd f = mean + a * v1 + b * v2;
    fields.append({30, 30, 30}, std::vector<double>(f.data(), f.data() + n));
    coefficients.push_back({a, b});
  }
  double mean_a = 0.0, mean_b = 0.0;
  for (const auto& [a, b] : coefficients) {
    mean_a += a / 400.0;
    mean_b += b / 400.0;
  }
  const ContactFieldPca pca = ContactFieldPca::fit(fields, 2);
  EXPECT_NEAR(pca.explainedVariance(), 1.0, 1e-9);
  // The two components span v1, v2 (rotated within that plane by the sample
  // correlation of a and b), so each row keeps its distance from the mean,
  // and the first carries the larger variance.
  double x[2], var0 = 0.0, var1 = 0.0;
  std::vector<double> row(n);
  for (size_t r = 0; r < coefficients.size(); ++r) {
    for (int i = 0; i < n; ++i) row[static_cast<size_t>(i)] = fields.sensedRow(r)[i];
    pca.project(row.data(), x);
    const double da = coefficients[r].first - mean_a, db = coefficients[r].second - mean_b;
    EXPECT_NEAR(std::hypot(x[0], x[1]), std::hypot(da, db), 1e-5);  // float storage
    var0 += x[0] * x[0];
    var1 += x[1] * x[1];
  }
  EXPECT_GT(var0, 2.0 * var1);
  EXPECT_THROW(ContactFieldPca::fit(fields, n + 1), InputError);
  const OnetipContactSensor grid;  // 75 channels, not the 12 of the fit
  EXPECT_THROW(PcaFeatureSensor(grid, pca), InputError);
}
