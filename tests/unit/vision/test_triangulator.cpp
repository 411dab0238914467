// Triangulation against independent ground truth: known 3-D points projected
// with a known calibration by cv::projectPoints (exact, and with pixel
// noise), the sensor frame and the deformation field derived from them, and
// OpenCV's real stereo photos (board geometry is exact there).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>
#include <iostream>
#include <map>
#include <opencv2/calib3d.hpp>

#include "core/calibration.hpp"
#include "core/csv_table.hpp"
#include "core/error.hpp"
#include "core/sensor_frame.hpp"
#include "vision/deformation_field.hpp"
#include "vision/triangulator.hpp"
#include "test_paths.hpp"

namespace onetip::vision {
namespace {

// A rig like the simulator's: two cameras 28 mm below the pad, 24 mm apart,
// each aimed at the pad centre; x right, y down, z forward.
struct Rig {
  StereoCalibration calib;
  Eigen::Isometry3d left_from_sensor = Eigen::Isometry3d::Identity();
};

Eigen::Isometry3d lookAtOrigin(const Eigen::Vector3d& centre) {
  const Eigen::Vector3d z = (-centre).normalized();
  const Eigen::Vector3d x = (Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitX().dot(z) * z).normalized();
  Eigen::Matrix3d R;
  R.row(0) = x.transpose();
  R.row(1) = z.cross(x).transpose();
  R.row(2) = z.transpose();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = R;
  T.translation() = -R * centre;
  return T;
}

Rig makeRig() {
  Rig rig;
  const Eigen::Isometry3d L = lookAtOrigin({-12, 0, -28}), Rc = lookAtOrigin({12, 0, -28});
  rig.left_from_sensor = L;
  const Eigen::Isometry3d right_from_left = Rc * L.inverse();
  StereoCalibration& c = rig.calib;
  c.image_width = 1920;
  c.image_height = 1080;
  c.split_x = 960;
  c.K_left = cv::Matx33d(1000, 0, 479.5, 0, 1002, 539.5, 0, 0, 1);
  c.K_right = cv::Matx33d(995, 0, 481.0, 0, 996, 541.0, 0, 0, 1);
  c.D_left = {-0.12, 0.04, 0.0004, -0.0003, 0.0};
  c.D_right = {-0.11, 0.03, -0.0002, 0.0005, 0.001};
  for (int r = 0; r < 3; ++r) {
    c.T[r] = right_from_left.translation()[r];
    for (int k = 0; k < 3; ++k) c.R(r, k) = right_from_left.linear()(r, k);
  }
  return rig;
}

// Pattern 17 x 17, 1.2 mm, flat at z = 0 in S, optionally pressed by a bump.
MarkerField padInSensor(double bump_mm) {
  MarkerField f(17, 17);
  for (int r = 0; r < 17; ++r)
    for (int c = 0; c < 17; ++c) {
      const double x = (c - 8) * 1.2, y = (r - 8) * 1.2;
      f.set(r * 17 + c, {x + 0.02 * bump_mm * y, y, -bump_mm * std::exp(-(x * x + y * y) / 20.0)});
    }
  return f;
}

struct Projected {
  std::vector<cv::Point2d> left, right;
};

Projected project(const Rig& rig, const std::vector<Eigen::Vector3d>& X_L) {
  std::vector<cv::Point3d> pts;
  for (const auto& X : X_L) pts.emplace_back(X.x(), X.y(), X.z());
  Projected p;
  cv::projectPoints(pts, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), rig.calib.K_left, rig.calib.D_left, p.left);
  cv::Vec3d rvec;
  cv::Rodrigues(rig.calib.R, rvec);
  cv::projectPoints(pts, rvec, rig.calib.T, rig.calib.K_right, rig.calib.D_right, p.right);
  return p;
}

std::vector<Eigen::Vector3d> toLeft(const Rig& rig, const MarkerField& S) {
  std::vector<Eigen::Vector3d> out;
  for (const auto& p : S.position) out.push_back(rig.left_from_sensor * p);
  return out;
}

TEST(Triangulator, ExactProjectionsComeBackToMicrometreFractions) {
  const Rig rig = makeRig();
  const auto X = toLeft(rig, padInSensor(1.5));
  const Projected px = project(rig, X);
  for (auto method : {TriangulationMethod::midpoint, TriangulationMethod::optimal}) {
    Triangulator tri(rig.calib, {method, 2.0});
    const auto out = tri.triangulatePairs(px.left, px.right);
    double worst = 0;
    for (size_t i = 0; i < X.size(); ++i) {
      ASSERT_TRUE(out[i].in_front);
      worst = std::max(worst, (out[i].X_L - X[i]).norm());
      EXPECT_LT(out[i].reprojection_px, 1e-6);
    }
    EXPECT_LT(worst, 1e-6) << "mm";
  }
}

TEST(Triangulator, NoisyProjectionsOptimalIsAtLeastAsGoodAsMidpoint) {
  const Rig rig = makeRig();
  const auto X = toLeft(rig, padInSensor(2.0));
  cv::RNG rng(7);
  double sq[2] = {0, 0};
  int n = 0;
  for (int trial = 0; trial < 20; ++trial) {
    Projected px = project(rig, X);
    for (auto* v : {&px.left, &px.right})
      for (auto& p : *v) p += cv::Point2d(rng.gaussian(0.1), rng.gaussian(0.1));
    int m = 0;
    for (auto method : {TriangulationMethod::midpoint, TriangulationMethod::optimal}) {
      const auto out = Triangulator(rig.calib, {method, 2.0}).triangulatePairs(px.left, px.right);
      for (size_t i = 0; i < X.size(); ++i) sq[m] += (out[i].X_L - X[i]).squaredNorm();
      ++m;
    }
    n += static_cast<int>(X.size());
  }
  const double rms_mid = std::sqrt(sq[0] / n), rms_opt = std::sqrt(sq[1] / n);
  std::cout << "3-D RMS error at 0.1 px noise: midpoint " << rms_mid << " mm, optimal " << rms_opt
            << " mm\n";
  EXPECT_LE(rms_opt, rms_mid * 1.001);
  EXPECT_LT(rms_opt, 0.02);  // the 3-D budget at the 2-D noise budget
  EXPECT_GT(rms_opt, 0.001);  // noise really went in
}

TEST(Triangulator, ViewMarkersMatchByIdAndRejectMismatches) {
  const Rig rig = makeRig();
  const auto X = toLeft(rig, padInSensor(0.0));
  const Projected px = project(rig, X);
  MarkerPattern pattern{17, 17, 1.2};
  ViewMarkers left(pattern), right(pattern);
  for (int id = 0; id < pattern.count(); ++id) {
    left.set(id, cv::Point2f(px.left[static_cast<size_t>(id)]));
    right.set(id, cv::Point2f(px.right[static_cast<size_t>(id)]));
  }
  left.clear(3);    // seen in one view only
  right.clear(40);
  std::swap(right.point[100], right.point[250]);  // a wrong correspondence
  const TriangulationResult r = Triangulator(rig.calib).triangulate(left, right);
  EXPECT_EQ(r.matched, pattern.count() - 2);
  EXPECT_EQ(r.rejected, 2);
  EXPECT_EQ(r.markers.validCount(), pattern.count() - 4);
  EXPECT_FALSE(r.markers.valid[3] || r.markers.valid[40] || r.markers.valid[100] || r.markers.valid[250]);
  double worst = 0;
  for (int id = 0; id < pattern.count(); ++id)
    if (r.markers.valid[static_cast<size_t>(id)])
      worst = std::max(worst, (r.markers.position[static_cast<size_t>(id)] - X[static_cast<size_t>(id)]).norm());
  EXPECT_LT(worst, 2e-4);  // float pixel coordinates
  EXPECT_LT(r.rms_reprojection_px, 1e-3);
  EXPECT_THROW(Triangulator(rig.calib).triangulate(left, ViewMarkers(MarkerPattern{5, 5, 1})), InputError);
}

TEST(Triangulator, RestFieldGivesTheSensorFrameAndDeformationField) {
  const Rig rig = makeRig();
  Triangulator tri(rig.calib);
  const auto fieldFrom = [&](const MarkerField& S) {
    const auto X = toLeft(rig, S);
    const Projected px = project(rig, X);
    MarkerField out(17, 17);
    const auto pts = tri.triangulatePairs(px.left, px.right);
    for (int i = 0; i < out.size(); ++i) out.set(i, pts[static_cast<size_t>(i)].X_L);
    return out;
  };
  const MarkerField rest_gt = padInSensor(0.0), now_gt = padInSensor(1.0);
  const MarkerField rest_L = fieldFrom(rest_gt);
  const SensorFrame S = SensorFrame::fromRestMarkers(rest_L);
  // The flat symmetric rest grid defines exactly the ground-truth S.
  const MarkerField rest_S = S.toSensor(rest_L), now_S = S.toSensor(fieldFrom(now_gt));
  for (int i = 0; i < rest_S.size(); ++i) {
    ASSERT_LT((rest_S.position[static_cast<size_t>(i)] - rest_gt.position[static_cast<size_t>(i)]).norm(), 1e-6);
    ASSERT_LT((now_S.position[static_cast<size_t>(i)] - now_gt.position[static_cast<size_t>(i)]).norm(), 1e-6);
  }
  const MarkerField d = markerDisplacement(now_S, rest_S);
  EXPECT_NEAR(d.position[8 * 17 + 8].z(), -1.0, 1e-6);  // the bump's peak, pressed in

  // A field linear in x, y is interpolated exactly; the bump closely.
  MarkerField linear(17, 17);
  const auto lin = [](const Eigen::Vector2d& q) { return Eigen::Vector3d(0.1 * q.x(), -0.2 * q.y(), 0.05 * q.x() + 0.3); };
  for (int i = 0; i < linear.size(); ++i) linear.set(i, lin(rest_S.position[static_cast<size_t>(i)].head<2>()));
  const DisplacementGrid g = interpolateDisplacement(rest_S, linear, {0.25});
  EXPECT_EQ(g.nx, 77);  // 19.2 mm / 0.25 + 1
  int valid = 0;
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix)
      if (g.valid[g.index(ix, iy)]) {
        ++valid;
        ASSERT_LT((g.displacement[g.index(ix, iy)] - lin(g.node(ix, iy))).norm(), 1e-9);
      }
  EXPECT_EQ(valid, g.nx * g.ny);  // the grid is inside the rest pad everywhere
  // The bump: exact at nodes on markers (every 4th node at 0.3 mm), elsewhere
  // within linear interpolation's bound h^2/8 * |f''| per axis (h = 1.2 mm,
  // |f''| <= 0.1 /mm for this bump): 2 * 0.018 mm.
  const DisplacementGrid bump = interpolateDisplacement(rest_S, d, {0.3});
  double worst_between = 0;
  for (int iy = 0; iy < bump.ny; ++iy)
    for (int ix = 0; ix < bump.nx; ++ix) {
      const Eigen::Vector2d q = bump.node(ix, iy);
      const double truth = -std::exp(-q.squaredNorm() / 20.0);
      const double got = bump.displacement[bump.index(ix, iy)].z();
      if (ix % 4 == 0 && iy % 4 == 0)
        ASSERT_NEAR(got, truth, 1e-6);
      else
        worst_between = std::max(worst_between, std::abs(got - truth));
    }
  EXPECT_LT(worst_between, 0.036);
  EXPECT_GT(worst_between, 0.001);  // really interpolated, not copied
  EXPECT_THROW(interpolateDisplacement(rest_S, d, {0.0}), InputError);
}

// OpenCV's stereo photos: reference corners + reference calibration must give
// a flat board of one-square spacing (exact geometry), and agree with the
// reference triangulation.
TEST(Triangulator, RealBoardsReproduceTheBoardGeometry) {
  const std::string dir = std::string(onetip::test::testDataDir()) + "/real/opencv_stereo_9x6/reference/";
  const StereoCalibration calib = loadCalibration(dir + "reference_calib_sbs_pairs01-09.yaml");
  const double square = 25.0;  // nominal mm: T in the file is squares x 25
  const CsvTable corners = readCsv(dir + "corners_pairs01-09.csv");
  const CsvTable reference = readCsv(dir + "triangulated_pairs01-09.csv");
  const MarkerPattern pattern{6, 9, square};
  std::map<std::string, ViewMarkers> views;
  for (const auto& row : corners.rows) {
    auto [it, fresh] = views.try_emplace(row[0], pattern);
    it->second.set(std::stoi(row[3]) * 9 + std::stoi(row[2]),
                   cv::Point2f(std::stof(row[4]), std::stof(row[5])));
  }
  std::map<std::string, std::vector<Eigen::Vector3d>> ref;
  for (const auto& row : reference.rows) {
    auto& v = ref[row[0]];
    v.resize(54);
    v[static_cast<size_t>(std::stoi(row[3]) * 9 + std::stoi(row[2]))] =
        square * Eigen::Vector3d(std::stod(row[4]), std::stod(row[5]), std::stod(row[6]));
  }
  // The default (midpoint) must reproduce the board; the reference file was made
  // with the optimal correction, so that method must reproduce it to 1e-3 squares.
  Triangulator tri(calib);
  TriangulatorOptions optimal;
  optimal.method = TriangulationMethod::optimal;
  Triangulator tri_optimal(calib, optimal);
  double worst_spacing = 0, worst_plane = 0, worst_ref = 0, worst_default_ref = 0;
  for (int pair = 1; pair <= 9; ++pair) {
    const std::string n = "0" + std::to_string(pair);
    const auto r = tri.triangulate(views.at("left" + n + ".jpg"), views.at("right" + n + ".jpg"));
    const auto r_opt = tri_optimal.triangulate(views.at("left" + n + ".jpg"), views.at("right" + n + ".jpg"));
    ASSERT_EQ(r.markers.validCount(), 54) << "pair " << n;
    double sum = 0;
    int links = 0;
    for (int row = 0; row < 6; ++row)
      for (int col = 0; col < 9; ++col) {
        const auto& p = r.markers.position[static_cast<size_t>(row * 9 + col)];
        if (col + 1 < 9) sum += (r.markers.position[static_cast<size_t>(row * 9 + col + 1)] - p).norm(), ++links;
        if (row + 1 < 6) sum += (r.markers.position[static_cast<size_t>((row + 1) * 9 + col)] - p).norm(), ++links;
      }
    const double spacing_error = std::abs(sum / links / square - 1.0);
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const auto& p : r.markers.position) centroid += p;
    centroid /= 54.0;
    Eigen::MatrixXd A(54, 3);
    for (int i = 0; i < 54; ++i) A.row(i) = (r.markers.position[static_cast<size_t>(i)] - centroid).transpose();
    const double plane_rms = Eigen::JacobiSVD<Eigen::MatrixXd>(A).singularValues()[2] / std::sqrt(54.0) / square;
    for (int i = 0; i < 54; ++i) {
      const Eigen::Vector3d& expected = ref.at("pair" + n)[static_cast<size_t>(i)];
      worst_ref = std::max(worst_ref, (r_opt.markers.position[static_cast<size_t>(i)] - expected).norm() / square);
      worst_default_ref = std::max(worst_default_ref, (r.markers.position[static_cast<size_t>(i)] - expected).norm() / square);
    }
    worst_spacing = std::max(worst_spacing, spacing_error);
    worst_plane = std::max(worst_plane, plane_rms);
  }
  std::cout << "real boards: worst mean-spacing error " << 100 * worst_spacing
            << " %, worst plane RMS " << worst_plane << " squares, worst gap to reference "
            << worst_ref << " squares (optimal), " << worst_default_ref << " squares (midpoint)\n";
  EXPECT_LT(worst_spacing, 0.005);
  EXPECT_LE(worst_plane, 0.025);
  EXPECT_LT(worst_ref, 1e-3);
  EXPECT_LT(worst_default_ref, 0.01);  // the two methods agree to 1% of a square on real photos
}

}  // namespace
}  // namespace onetip::vision
