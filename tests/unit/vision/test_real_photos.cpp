// Corner detection and id assignment on real photos (OpenCV's sample sets,
// tests/data/real/README.md): every corner of every image, numbering
// consistent between the two views of a stereo pair, positions against the
// reference corners (OpenCV findChessboardCorners + cornerSubPix, a +-0.3 px
// reference) compared without depending on the 180-deg numbering.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "core/csv_table.hpp"
#include "vision/grid_tracker.hpp"
#include "test_paths.hpp"

namespace onetip::vision {
namespace {

const std::string kStereoDir = std::string(onetip::test::testDataDir()) + "/real/opencv_stereo_9x6/";

using PointTable = std::map<int, cv::Point2f>;  // index -> position

std::map<std::string, PointTable> readReference(const std::string& path, bool with_image) {
  const CsvTable t = readCsv(path);
  const size_t ci = t.column("index", path), cx = t.column("x", path), cy = t.column("y", path);
  std::map<std::string, PointTable> out;
  for (const auto& row : t.rows) {
    const std::string image = with_image ? row[t.column("image", path)] : "";
    out[image][static_cast<int>(parseNumber(row[ci], path))] =
        cv::Point2f(static_cast<float>(parseNumber(row[cx], path)), static_cast<float>(parseNumber(row[cy], path)));
  }
  return out;
}

struct Comparison {
  bool reversed = false;  // our id i matched reference index (count - 1 - i)
  double rms = 0, max = 0;
};

// Our markers against the reference under the numbering (direct or turned by
// 180 deg) that fits better.
Comparison compare(const ViewMarkers& ours, const PointTable& reference) {
  Comparison best;
  best.rms = 1e9;
  for (bool reversed : {false, true}) {
    double sum = 0, worst = 0;
    for (int id = 0; id < ours.size(); ++id) {
      const cv::Point2f d = ours.point[static_cast<size_t>(id)] - reference.at(reversed ? ours.size() - 1 - id : id);
      sum += d.dot(d);
      worst = std::max(worst, std::sqrt(static_cast<double>(d.dot(d))));
    }
    const double rms = std::sqrt(sum / ours.size());
    if (rms < best.rms) best = {reversed, rms, worst};
  }
  return best;
}

TEST(RealPhotos, StereoPairsAllCornersConsistentNumbering) {
  const auto reference = readReference(kStereoDir + "reference/corners_pairs01-09.csv", true);
  const MarkerPattern board{6, 9, 25.0};
  double sum2 = 0;
  int n = 0;
  for (int pair = 1; pair <= 9; ++pair) {
    bool reversed[2] = {false, false};
    for (int side = 0; side < 2; ++side) {
      const std::string name = std::string(side == 0 ? "left" : "right") + "0" + std::to_string(pair) + ".jpg";
      const cv::Mat grey = cv::imread(kStereoDir + name, cv::IMREAD_GRAYSCALE);
      ASSERT_FALSE(grey.empty()) << name;
      const GridResult r = detectBoard(grey, board);
      ASSERT_TRUE(r.ok()) << name << ": " << r.message;
      ASSERT_EQ(r.found, 54) << name;
      const Comparison c = compare(r.markers, reference.at(name));
      EXPECT_LT(c.rms, 0.3) << name;  // the reference is good to about +-0.3 px
      EXPECT_LT(c.max, 0.8) << name;
      reversed[side] = c.reversed;
      sum2 += c.rms * c.rms * 54, n += 54;
      std::printf("%s rms %.3f max %.3f\n", name.c_str(), c.rms, c.max);
    }
    EXPECT_EQ(reversed[0], reversed[1]) << "pair " << pair << ": left and right numbered differently";
  }
  std::printf("all 18 images: RMS vs reference %.3f px\n", std::sqrt(sum2 / n));
}

// Mono calibration (OpenCV) of one camera's nine views from the given corners:
// the reprojection RMS measures how well the corners fit one exact planar grid
// seen through one lens, i.e. their accuracy, without trusting any reference.
double calibrationRms(const std::vector<std::vector<cv::Point2f>>& views) {
  std::vector<cv::Point3f> board;
  for (int id = 0; id < 54; ++id) board.emplace_back(static_cast<float>(id % 9), static_cast<float>(id / 9), 0.0f);
  const std::vector<std::vector<cv::Point3f>> objects(views.size(), board);
  cv::Mat K, D;
  std::vector<cv::Mat> rvecs, tvecs;
  return cv::calibrateCamera(objects, views, cv::Size(640, 480), K, D, rvecs, tvecs);
}

TEST(RealPhotos, CalibrationResidualNoWorseThanOpenCvCorners) {
  const auto reference = readReference(kStereoDir + "reference/corners_pairs01-09.csv", true);
  for (const std::string side : {"left", "right"}) {
    std::vector<std::vector<cv::Point2f>> ours, theirs;
    for (int pair = 1; pair <= 9; ++pair) {
      const std::string name = side + "0" + std::to_string(pair) + ".jpg";
      const GridResult r = detectBoard(cv::imread(kStereoDir + name, cv::IMREAD_GRAYSCALE), MarkerPattern{6, 9, 25.0});
      ASSERT_EQ(r.found, 54) << name;
      ours.push_back(r.markers.point);
      std::vector<cv::Point2f> ref;
      // Reference numbering turned to match ours (the board is 180-deg symmetric).
      const bool reversed = compare(r.markers, reference.at(name)).reversed;
      for (int id = 0; id < 54; ++id) ref.push_back(reference.at(name).at(reversed ? 53 - id : id));
      theirs.push_back(ref);
    }
    const double rms_ours = calibrationRms(ours), rms_theirs = calibrationRms(theirs);
    std::printf("%s camera calibration RMS: our corners %.3f px, OpenCV reference corners %.3f px\n", side.c_str(),
                rms_ours, rms_theirs);
    EXPECT_LE(rms_ours, rms_theirs) << side;
  }
}

TEST(RealPhotos, SideBySideFramesAnchoredInEachView) {
  // The derived side-by-side frames: both views of a pair get the same ids.
  StereoCalibration calib;
  calib.image_width = 1280, calib.image_height = 480, calib.split_x = 640;
  const MarkerPattern board{6, 9, 25.0};
  for (int pair = 1; pair <= 9; ++pair) {
    const cv::Mat frame = cv::imread(kStereoDir + "sbs/pair0" + std::to_string(pair) + ".png", cv::IMREAD_GRAYSCALE);
    const StereoViews views = splitViews(frame, calib);
    const GridResult left = detectBoard(views.left, board), right = detectBoard(views.right, board);
    ASSERT_TRUE(left.ok() && right.ok()) << "pair " << pair << ": " << left.message << right.message;
    // Corresponding ids lie on the same board corner: the right view is the
    // left one shifted by the baseline disparity, so the id order agrees.
    for (int id : {0, 8, 45, 53}) {
      const cv::Point2f l = left.markers.point[static_cast<size_t>(id)], r = right.markers.point[static_cast<size_t>(id)];
      EXPECT_LT(std::abs(l.y - r.y), 40.0f) << "pair " << pair << " id " << id;
    }
  }
}

TEST(RealPhotos, SyntheticChessboardPngAgainstGroundTruth) {
  const std::string dir = std::string(onetip::test::testDataDir()) + "/real/opencv_chessboard_png/";
  const cv::Mat rgba = cv::imread(dir + "chessboard.png", cv::IMREAD_UNCHANGED);
  ASSERT_FALSE(rgba.empty());
  cv::Mat grey;
  cv::cvtColor(rgba, grey, rgba.channels() == 4 ? cv::COLOR_BGRA2GRAY : cv::COLOR_BGR2GRAY);
  const auto gt = readReference(dir + "chessboard_png_corners_gt.csv", false).at("");
  CornerDetectorOptions options;
  options.prefilter_downsample = 4;
  const GridResult r = detectBoard(grey, MarkerPattern{7, 7, 1.0}, options);
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(r.found, 49);
  for (int id = 0; id < 49; ++id) {  // row-major from the top-left, as our anchoring
    const cv::Point2f d = r.markers.point[static_cast<size_t>(id)] - gt.at(id);
    EXPECT_LT(std::abs(d.x), 0.35f) << "id " << id;
    EXPECT_LT(std::abs(d.y), 0.1f) << "id " << id;
  }
}

}  // namespace
}  // namespace onetip::vision
