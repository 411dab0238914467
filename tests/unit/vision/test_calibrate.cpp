// Stereo calibration: the board numbering, the solver against a known rig
// (exact synthetic views), and `onetip calibrate` on OpenCV's real stereo
// photos against the reference calibration, plus its bad-input contract.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/calibration.hpp"
#include "core/error.hpp"
#include "core/pattern.hpp"
#include "vision/calibration_board.hpp"
#include "vision/stereo_calibration.hpp"
#include "calibrate_cli.hpp"
#include "scratch_dir.hpp"
#include "test_paths.hpp"

namespace onetip::vision {
namespace {

namespace fs = std::filesystem;

const std::string kReal = std::string(onetip::test::testDataDir()) + "/real/opencv_stereo_9x6/";

std::vector<cv::Point2f> gridAt(int rows, int cols, double angle_deg, bool mirrored) {
  std::vector<cv::Point2f> g;
  const double a = angle_deg * CV_PI / 180.0;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const double x = mirrored ? -c * 20.0 : c * 20.0, y = r * 20.0;
      g.emplace_back(static_cast<float>(300 + std::cos(a) * x - std::sin(a) * y),
                     static_cast<float>(200 + std::sin(a) * x + std::cos(a) * y));
    }
  return g;
}

TEST(CalibrationBoard, NumberingIsAnchoredInTheImageAndAlignedAcrossViews) {
  for (int rows : {6, 7})
    for (double angle : {0.0, 30.0, 80.0, 150.0, 180.0, 250.0, -60.0})
      for (bool mirrored : {false, true}) {
        const auto g = anchorBoardNumbering(gridAt(rows, 7, angle, mirrored), rows, 7);
        const cv::Point2f col = g[1] - g[0], row = g[7] - g[0];
        EXPECT_GT(col.x * row.y - col.y * row.x, 0) << angle;  // right-handed
        // col within 45 deg of +x for square boards, within 90 deg otherwise
        EXPECT_GT(col.x, rows == 7 ? 0.70f * 20 : 0.0f) << rows << " " << angle << " " << mirrored;
        // Another view of the same board turned a further 10 deg: numbered alike.
        const auto other = alignBoardNumbering(g, gridAt(rows, 7, angle + 10, mirrored), rows, 7);
        const cv::Point2f ocol = other[1] - other[0];
        EXPECT_GT(ocol.dot(col), 0.9f * 400) << angle;
      }
}

// A known rig and a board in 8 poses, projected exactly: the solver must
// return that rig.
TEST(StereoCalibration, RecoversAKnownRigFromExactViews) {
  StereoCalibration truth;
  truth.image_width = 1280;
  truth.image_height = 480;
  truth.split_x = 640;
  truth.K_left = cv::Matx33d(520, 0, 322, 0, 522, 238, 0, 0, 1);
  truth.K_right = cv::Matx33d(530, 0, 318, 0, 529, 244, 0, 0, 1);
  truth.D_left = {-0.25, 0.09, 0.001, -0.0005, 0.0};
  truth.D_right = {-0.28, 0.11, -0.0008, 0.0004, 0.0};
  cv::Rodrigues(cv::Vec3d(0.01, -0.02, 0.005), truth.R);
  truth.T = {-80.0, 1.0, 0.5};
  const MarkerPattern pattern{6, 9, 25};
  std::vector<cv::Point3d> board;
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 9; ++c) board.emplace_back(c * 25.0, r * 25.0, 0.0);
  std::vector<BoardViewPair> pairs;
  cv::Vec3d rR;
  cv::Rodrigues(truth.R, rR);
  for (int k = 0; k < 8; ++k) {
    const cv::Vec3d rvec(0.3 * std::sin(k), 0.3 * std::cos(1.3 * k), 0.2 * k - 0.7);
    const cv::Vec3d tvec(-100 + 10 * k, -60 + 5 * (k % 3), 380 + 15 * k);
    cv::Matx33d Rb;
    cv::Rodrigues(rvec, Rb);
    std::vector<cv::Point2d> l, r;
    cv::projectPoints(board, rvec, tvec, truth.K_left, truth.D_left, l);
    // Right camera: X_R = R (Rb X + t) + T.
    cv::Vec3d rvec_r;
    cv::Rodrigues(truth.R * Rb, rvec_r);
    cv::projectPoints(board, rvec_r, truth.R * tvec + truth.T, truth.K_right, truth.D_right, r);
    BoardViewPair p;
    for (size_t i = 0; i < l.size(); ++i) {
      p.left.emplace_back(l[i]);
      p.right.emplace_back(r[i]);
    }
    pairs.push_back(p);
  }
  const StereoCalibrationResult res = calibrateStereo(pairs, pattern, truth);
  EXPECT_EQ(res.pairs_used, 8);
  EXPECT_LT(res.rms_px, 1e-3);  // float corners only
  const StereoCalibration& c = res.calibration;
  EXPECT_EQ(c.split_x, 640);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(c.K_left(i, j), truth.K_left(i, j), 0.05);
      EXPECT_NEAR(c.K_right(i, j), truth.K_right(i, j), 0.05);
      EXPECT_NEAR(c.R(i, j), truth.R(i, j), 1e-4);
    }
  EXPECT_LT(cv::norm(c.T - truth.T), 0.05);  // mm
  EXPECT_THROW(calibrateStereo({pairs[0], pairs[1]}, pattern, truth), InputError);  // < 3 pairs
}

using onetip::test::CliRun;
using onetip::test::lastLine;

CliRun runCli(const std::string& args) { return onetip::test::runCalibrate(args); }

double angleDeg(const cv::Matx33d& A, const cv::Matx33d& B) {
  cv::Vec3d r;
  cv::Rodrigues(A * B.t(), r);
  return cv::norm(r) * 180.0 / CV_PI;
}

// Distortion compared through undistorted points (README: k3 is poorly
// constrained): the worst gap, in pixels, over a grid covering the view.
double undistortGapPx(const cv::Matx33d& K1, const cv::Vec<double, 5>& D1, const cv::Matx33d& K2,
                      const cv::Vec<double, 5>& D2) {
  std::vector<cv::Point2d> px, a, b;
  for (int y = 40; y <= 440; y += 50)
    for (int x = 40; x <= 600; x += 70) px.emplace_back(x, y);
  cv::undistortPoints(px, a, K1, D1, cv::noArray(), K1);
  cv::undistortPoints(px, b, K2, D2, cv::noArray(), K1);
  double worst = 0;
  for (size_t i = 0; i < px.size(); ++i) worst = std::max(worst, cv::norm(a[i] - b[i]));
  return worst;
}

TEST(CalibrateCommand, RealStereoPhotosMatchTheReference) {
  const onetip::test_support::ScratchDir dir("onetip-calib");
  const std::string out = dir.file("c.yaml");
  const std::string pattern = kReal + "reference/pattern_9x6_nominal25mm.yaml";
  const CliRun run = runCli("--pattern " + pattern + " --input " + kReal + "sbs --out " + out);
  ASSERT_EQ(run.status, 0) << run.out;
  const double rms = std::stod(lastLine(run.out).substr(lastLine(run.out).rfind(' ')));
  const StereoCalibration ref = loadCalibration(kReal + "reference/reference_calib_sbs_pairs01-09.yaml");
  std::cout << "calibrate on real photos: RMS " << rms << " px (reference 0.2184)\n";
  EXPECT_LE(rms, 0.2184 * 1.10);
  EXPECT_NE(run.out.find("9 of 9"), std::string::npos) << run.out;
  const StereoCalibration c = loadCalibration(out);
  EXPECT_EQ(c.split_x, 640);
  for (auto [K, Kr] : {std::pair{c.K_left, ref.K_left}, std::pair{c.K_right, ref.K_right}}) {
    EXPECT_NEAR(K(0, 0) / Kr(0, 0), 1.0, 0.01);
    EXPECT_NEAR(K(1, 1) / Kr(1, 1), 1.0, 0.01);
    EXPECT_NEAR(K(0, 2), Kr(0, 2), 5.0);
    EXPECT_NEAR(K(1, 2), Kr(1, 2), 5.0);
  }
  EXPECT_LT(undistortGapPx(c.K_left, c.D_left, ref.K_left, ref.D_left), 0.5);
  EXPECT_LT(undistortGapPx(c.K_right, c.D_right, ref.K_right, ref.D_right), 0.5);
  EXPECT_NEAR(cv::norm(c.T) / cv::norm(ref.T), 1.0, 0.01);
  EXPECT_LT(angleDeg(c.R, ref.R), 0.5);

  // The same frames with both halves mirrored, calibrated with the flips:
  // the views after the flip are the originals, so the result is the same.
  const onetip::test_support::ScratchDir flipped("onetip-calib");
  onetip::test::writeMirroredPairs(kReal + "sbs", flipped.path().string(), true, true);
  const std::string out2 = dir.file("flipped.yaml");
  const CliRun run2 = runCli("--pattern " + pattern + " --input " + flipped.path().string() + " --out " +
                             out2 + " --split-x 640 --flip-left --flip-right");
  ASSERT_EQ(run2.status, 0) << run2.out;
  const StereoCalibration c2 = loadCalibration(out2);
  EXPECT_TRUE(c2.flip_left && c2.flip_right);
  EXPECT_LE(std::stod(lastLine(run2.out).substr(lastLine(run2.out).rfind(' '))), 0.2184 * 1.10);
  // A flip applied wrongly would move the principal points by 2 cx - 639 px.
  for (auto [K, Kr] : {std::pair{c2.K_left, ref.K_left}, std::pair{c2.K_right, ref.K_right}}) {
    EXPECT_NEAR(K(0, 0) / Kr(0, 0), 1.0, 0.01);
    EXPECT_NEAR(K(0, 2), Kr(0, 2), 5.0);
    EXPECT_NEAR(K(1, 2), Kr(1, 2), 5.0);
  }
  EXPECT_NEAR(cv::norm(c2.T) / cv::norm(ref.T), 1.0, 0.01);
  EXPECT_LT(angleDeg(c2.R, ref.R), 0.5);
}

TEST(CalibrateCommand, JointRefinementBeatsFixedIntrinsicsOnRealPhotos) {
  StereoCalibration layout;
  layout.image_width = 1280;
  layout.image_height = 480;
  layout.split_x = 640;
  const MarkerPattern pattern{6, 9, 25};
  std::vector<BoardViewPair> pairs;
  for (int i = 1; i <= 9; ++i) {
    const cv::Mat f = cv::imread(kReal + "sbs/pair0" + std::to_string(i) + ".png", cv::IMREAD_GRAYSCALE);
    ViewHalf l{f(cv::Rect(0, 0, 640, 480)), false}, r{f(cv::Rect(640, 0, 640, 480)), false};
    auto a = findCalibrationBoard(l, pattern), b = findCalibrationBoard(r, pattern);
    ASSERT_TRUE(a && b) << i;
    pairs.push_back({*a, alignBoardNumbering(*a, *b, 6, 9)});
  }
  const double joint = calibrateStereo(pairs, pattern, layout, {true, 3}).rms_px;
  const double fixed = calibrateStereo(pairs, pattern, layout, {false, 3}).rms_px;
  std::cout << "stereo RMS: joint " << joint << " px, fixed intrinsics " << fixed << " px\n";
  EXPECT_LE(joint, fixed);
  EXPECT_NEAR(fixed, 0.2207, 0.01);  // reference stereo_fixed_intrinsics
}

TEST(CalibrateCommand, BadInputExitsNonZeroWithOneLineAndNoFile) {
  const onetip::test_support::ScratchDir dir("onetip-calib");
  const std::string out = dir.file("c.yaml");
  const std::string pattern = kReal + "reference/pattern_9x6_nominal25mm.yaml";
  fs::create_directories(dir.file("empty"));
  fs::create_directories(dir.file("noboard"));
  cv::Mat no_board(480, 1280, CV_8UC1);
  for (int y = 0; y < 480; ++y) no_board.row(y).setTo(y / 2);  // a smooth ramp, no corners
  cv::imwrite(dir.file("noboard/f0.png"), no_board);
  std::ofstream(dir.file("bad_pattern.yaml")) << "%YAML:1.0\n---\nrows: 6\ncols: 1\nsquare_mm: 25\n";
  std::ofstream(dir.file("broken.yaml")) << "rows: [6\ncols: {9\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--pattern " + pattern + " --input " + dir.file("missing") + " --out " + out, "missing"},
      {"--pattern " + pattern + " --input " + dir.file("empty") + " --out " + out, "no image"},
      {"--pattern " + pattern + " --input " + dir.file("noboard") + " --out " + out, "not found"},
      {"--pattern " + dir.file("bad_pattern.yaml") + " --input " + kReal + "sbs --out " + out, "cols"},
      {"--pattern " + dir.file("broken.yaml") + " --input " + kReal + "sbs --out " + out, "broken.yaml"},
      {"--pattern " + dir.file("none.yaml") + " --input " + kReal + "sbs --out " + out, "none.yaml"},
      {"--pattern " + pattern + " --input " + kReal + "sbs --out " + out + " --split-x 5000", "split"},
      {"--pattern " + pattern + " --input " + kReal + "sbs", "--out"},
  };
  for (const auto& [args, says] : cases) {
    const CliRun run = runCli(args);
    EXPECT_NE(run.status, 0) << args;
    const std::string line = lastLine(run.out);
    EXPECT_NE(line.find(says), std::string::npos) << args << "\n" << run.out;
    EXPECT_EQ(line.rfind("onetip calibrate: ", 0), 0u) << run.out;  // one line, the whole message
    EXPECT_FALSE(fs::exists(out)) << args;
  }
}

}  // namespace
}  // namespace onetip::vision
